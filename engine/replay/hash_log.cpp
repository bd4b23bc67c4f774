// Hash logs: parsing (positioned errors) and writing of golden/<script>/hashes.txt.
#include "replay/hash_log.h"

#include <charconv>
#include <sstream>

#include "core/error.h"
#include "core/input_limits.h"
#include "replay/script.h"

namespace arc::replay {

HashLog parse_hash_log(const std::string& text, const std::string& path) {
  check_text_size(text.size(), path, kMaxScriptFileBytes, "a hash log");
  HashLog log;
  std::istringstream in(text);
  std::string l;
  int line = 0;
  auto fail = [&](int col, const std::string& m) {
    throw InputError(path + ":" + std::to_string(line) + ":" + std::to_string(col) + ": " + m);
  };
  while (std::getline(in, l)) {
    ++line;
    if (!l.empty() && l.back() == '\r') l.pop_back();
    if (line == 1) {
      if (l != "arcfire-hashlog 1") fail(1, "a hash log starts with 'arcfire-hashlog 1'");
      continue;
    }
    if (l.empty()) continue;
    size_t sp = l.find(' ');
    uint64_t tick = 0, value = 0;
    auto [p, ec] = std::from_chars(l.data(), l.data() + (sp == std::string::npos ? l.size() : sp), tick);
    if (sp == std::string::npos || ec != std::errc() || p != l.data() + sp)
      fail(1, "expected 'TICK HEX', got '" + l + "'");
    if (tick != log.hashes.size())
      fail(1, "expected tick " + std::to_string(log.hashes.size()) + ", got " + std::to_string(tick) +
                  " (ticks are consecutive from 0)");
    size_t sp2 = l.find(' ', sp + 1);
    size_t stop = sp2 == std::string::npos ? l.size() : sp2;
    auto [q, ec2] = std::from_chars(l.data() + sp + 1, l.data() + stop, value, 16);
    // Exactly 16 digits, as written: a log cut short mid-line is refused, not read as a small value.
    if (ec2 != std::errc() || q != l.data() + stop || stop - sp - 1 != 16)
      fail(static_cast<int>(sp) + 2, "hash must be 16 hex digits, got '" + l.substr(sp + 1, stop - sp - 1) + "'");
    log.hashes.push_back(value);
    if (sp2 == std::string::npos) continue;
    uint64_t full = 0;
    auto [r, ec3] = std::from_chars(l.data() + sp2 + 1, l.data() + l.size(), full, 16);
    if (ec3 != std::errc() || r != l.data() + l.size() || l.size() - sp2 - 1 != 16)
      fail(static_cast<int>(sp2) + 2, "full hash must be 16 hex digits, got '" + l.substr(sp2 + 1) + "'");
    log.full.emplace_back(tick, full);
  }
  if (line == 0) throw InputError(path + ":1:1: empty hash log; it starts with 'arcfire-hashlog 1'");
  if (text.back() != '\n') {
    const size_t last_line = text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1;
    fail(int(text.size() - last_line) + 1,
         "the file is cut short (its last line has no line end); run --update-golden to write it again");
  }
  return log;
}

std::string write_hash_log(const HashLog& log) {
  std::string out = "arcfire-hashlog 1\n";
  out.reserve(out.size() + log.hashes.size() * 24);
  size_t f = 0;
  for (size_t t = 0; t < log.hashes.size(); ++t) {
    out += std::to_string(t);
    out += ' ';
    out += hex64(log.hashes[t]);
    if (f < log.full.size() && log.full[f].first == t) {
      out += ' ';
      out += hex64(log.full[f++].second);
    }
    out += '\n';
  }
  return out;
}

}  // namespace arc::replay
