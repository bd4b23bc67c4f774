#include "game/workbench/effect_document.h"

#include <system_error>

#include "core/error.h"
#include "core/file_writer.h"
#include "core/json.h"
#include "game/workbench/json_splice.h"

namespace arc {
namespace {

// Runs a splice; its InputError (a pointer that names nothing) becomes a refused edit.
template <typename F>
bool spliced(F&& splice, std::string& out, std::string& error) {
  try {
    out = splice();
    return true;
  } catch (const InputError& e) {
    error = e.what();
    return false;
  }
}

}  // namespace

std::unique_ptr<EffectDocument> EffectDocument::open(const std::string& path, std::string& error) {
  std::unique_ptr<EffectDocument> doc(new EffectDocument());
  doc->path_ = path;
  bool ok = false;
  std::string text = doc->read_disk(ok);
  if (!ok) {
    error = path + ": cannot open file (missing or unreadable)";
    return nullptr;
  }
  State s;
  if (!doc->validate(text, s, error)) return nullptr;
  doc->adopt(std::move(s));
  doc->disk_text_ = doc->seen_disk_text_ = text;
  return doc;
}

std::string EffectDocument::name() const { return std::filesystem::path(path_).stem().string(); }

const EffectDef& EffectDocument::def() const { return library_->get(name()); }

bool EffectDocument::validate(const std::string& text, State& out, std::string& error) const {
  try {
    auto library = std::make_shared<EffectLibrary>();
    library->load_text(text, path_);
    out.json = nlohmann::json::parse(text, nullptr, true, true);
    out.text = text;
    out.library = std::move(library);
    return true;
  } catch (const InputError& e) {
    error = e.what();
  } catch (const nlohmann::json::exception& e) {
    error = path_ + ": " + e.what();
  }
  return false;
}

EffectDocument::State EffectDocument::current() const { return State{text_, json_, library_}; }

void EffectDocument::adopt(State s) {
  text_ = std::move(s.text);
  json_ = std::move(s.json);
  library_ = std::move(s.library);
  ++revision_;
}

EditResult EffectDocument::apply(std::string text, bool merge) {
  if (!merge) dragging_.clear();
  if (text == text_) return {};
  State s;
  std::string error;
  if (!validate(text, s, error)) return {false, error};
  if (!merge || undo_.empty()) undo_.push_back(current());
  redo_.clear();
  adopt(std::move(s));
  return {};
}

EditResult EffectDocument::set(const std::string& pointer, const nlohmann::json& value) {
  std::string text, error;
  if (!spliced([&] { return splice_set(text_, path_, pointer, value); }, text, error)) return {false, error};
  return apply(std::move(text));
}

EditResult EffectDocument::drag(const std::string& pointer, const nlohmann::json& value) {
  std::string text, error;
  if (!spliced([&] { return splice_set(text_, path_, pointer, value); }, text, error)) return {false, error};
  if (text == text_) return {};  // a drag begins with its first change (its undo step holds the text before it)
  const bool merge = dragging_ == pointer;
  EditResult r = apply(std::move(text), merge);
  if (r.ok) dragging_ = pointer;
  return r;
}

EditResult EffectDocument::remove(const std::string& pointer) {
  std::string text, error;
  if (!spliced([&] { return splice_remove(text_, path_, pointer); }, text, error)) return {false, error};
  return apply(std::move(text));
}

EditResult EffectDocument::insert(const std::string& array_pointer, size_t index, const nlohmann::json& value) {
  std::string text, error;
  if (!spliced([&] { return splice_insert(text_, path_, array_pointer, index, value); }, text, error))
    return {false, error};
  return apply(std::move(text));
}

EditResult EffectDocument::duplicate(const std::string& element_pointer) {
  std::string text, error;
  if (!spliced([&] { return splice_duplicate(text_, path_, element_pointer); }, text, error)) return {false, error};
  return apply(std::move(text));
}

EditResult EffectDocument::move(const std::string& array_pointer, size_t from, size_t to) {
  std::string text, error;
  if (!spliced([&] { return splice_move(text_, path_, array_pointer, from, to); }, text, error)) return {false, error};
  return apply(std::move(text));
}

bool EffectDocument::undo() {
  dragging_.clear();
  if (undo_.empty()) return false;
  redo_.push_back(current());
  State s = std::move(undo_.back());
  undo_.pop_back();
  adopt(std::move(s));
  return true;
}

bool EffectDocument::redo() {
  dragging_.clear();
  if (redo_.empty()) return false;
  undo_.push_back(current());
  State s = std::move(redo_.back());
  redo_.pop_back();
  adopt(std::move(s));
  return true;
}

std::string EffectDocument::read_disk(bool& ok) {
  std::error_code ec;
  ok = false;
  const auto time = std::filesystem::last_write_time(path_, ec);
  if (ec) return {};
  try {
    std::string text = read_text_file(path_);
    ok = true;
    disk_time_ = time;  // the stat goes with the text it describes
    disk_size_ = text.size();
    return text;
  } catch (const InputError&) {
    return {};
  }
}

void EffectDocument::save() {
  write_file_atomic(path_, text_);
  bool ok = false;
  read_disk(ok);
  disk_text_ = seen_disk_text_ = text_;
}

DiskChange EffectDocument::poll() {
  std::error_code ec;
  const auto time = std::filesystem::last_write_time(path_, ec);
  const uintmax_t size = ec ? 0 : std::filesystem::file_size(path_, ec);
  if (ec || (time == disk_time_ && size == disk_size_)) return DiskChange::Unchanged;
  bool ok = false;
  const std::string text = read_disk(ok);
  if (!ok || text == seen_disk_text_) return DiskChange::Unchanged;
  seen_disk_text_ = text;
  if (dirty()) return DiskChange::Conflict;
  const EditResult r = reload();
  return r.ok ? DiskChange::Reloaded : DiskChange::Invalid;
}

void EffectDocument::keep_mine() { disk_error_.clear(); }

EditResult EffectDocument::reload() {
  State s;
  std::string error;
  if (!validate(seen_disk_text_, s, error)) {
    disk_error_ = error;
    return {false, error};
  }
  disk_error_.clear();
  disk_text_ = seen_disk_text_;
  dragging_.clear();
  if (s.text != text_) {
    undo_.push_back(current());
    redo_.clear();
    adopt(std::move(s));
  }
  return {};
}

}  // namespace arc
