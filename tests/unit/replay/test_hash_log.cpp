#include <gtest/gtest.h>

#include "core/error.h"
#include "replay/hash_log.h"

using namespace arc::replay;

TEST(HashLog, RoundTripWithFullHashes) {
  HashLog log;
  log.hashes = {1, 0xffffffffffffffffULL, 0x1234};
  log.full = {{0, 0xabcdef}, {2, 7}};
  std::string text = write_hash_log(log);
  EXPECT_EQ(text, "arcfire-hashlog 1\n0 0000000000000001 0000000000abcdef\n1 ffffffffffffffff\n"
                  "2 0000000000001234 0000000000000007\n");
  HashLog back = parse_hash_log(text, "h.txt");
  EXPECT_EQ(back.hashes, log.hashes);
  EXPECT_EQ(back.full, log.full);
}

TEST(HashLog, BadLinesArePositioned) {
  auto err = [](const std::string& t) {
    try {
      parse_hash_log(t, "h.txt");
    } catch (const arc::InputError& e) {
      return std::string(e.what());
    }
    return std::string("(none)");
  };
  EXPECT_EQ(err("nope\n").rfind("h.txt:1:1: a hash log starts with", 0), 0u) << err("nope\n");
  const std::string h = "0000000000000001";
  EXPECT_EQ(err("arcfire-hashlog 1\n0 " + h + "\n2 " + h + "\n").rfind("h.txt:3:1: expected tick 1, got 2", 0), 0u);
  EXPECT_EQ(err("arcfire-hashlog 1\n0 zz\n").rfind("h.txt:2:3: hash must be", 0), 0u);
  EXPECT_EQ(err("arcfire-hashlog 1\n0 " + h + " q\n").rfind("h.txt:2:20: full hash must be", 0), 0u);
  // Cut short: mid-value, and mid-line after a whole value.
  EXPECT_EQ(err("arcfire-hashlog 1\n0 " + h + " 00000\n").rfind("h.txt:2:20: full hash must be 16 hex digits", 0), 0u);
  EXPECT_EQ(err("arcfire-hashlog 1\n0 " + h).rfind("h.txt:2:19: the file is cut short", 0), 0u) << err("arcfire-hashlog 1\n0 " + h);
  EXPECT_EQ(err("").rfind("h.txt:1:1: empty hash log", 0), 0u);
}
