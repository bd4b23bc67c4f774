// workbench/effect_document.h — the effect workbench's edit model (no GL): one effect file open
// for editing, every edit validated by the game's own loader, undo/redo, comment-preserving save.
//
// The document's state is the file's text. An edit (set, insert, remove, move) is made by
// splicing new bytes into that text at the byte spans core/json records for every value, and the
// result is loaded by EffectLibrary::load_text exactly as the game loads the file: an edit the
// loader refuses changes nothing and returns the loader's one line (`path:line:col: ...`, with
// the position the value would have in the saved file). Because edits are splices, saving an
// untouched file writes the same bytes, changing one number changes only its bytes, comments
// and formatting of everything not edited survive, a new key is written in the file's own
// indentation, and a removed key or array element goes with its line.
//
// Field kinds, ranges, allowed values and defaults for the panel come from
// particles/effect_schema.h, the table the loader reads its ranges from.
//
// Example, compiled as WorkbenchExamples.EditAnEffect in tests/unit/workbench/test_workbench_examples.cpp:
//   std::string error;
//   std::unique_ptr<EffectDocument> doc = EffectDocument::open(path, error);  // e.g. assets/effects/plasma_bolt.json
//   EditResult r = doc->set("/clusters/0/emitter/rate", 120);     // r.ok, or r.message from the loader
//   doc->undo();  doc->redo();
//   doc->save();                                                   // atomic; throws InputError
//   if (doc->poll() == DiskChange::Conflict) doc->keep_mine();     // or doc->reload()
//   ParticleWorld world(config, doc->library().get());             // rebuild when revision() changes
#pragma once
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>
#include <nlohmann/json.hpp>

#include "particles/effect_def.h"
#include "particles/effect_library.h"
#include "particles/effect_schema.h"

namespace arc {

struct EditResult {
  bool ok = true;
  std::string message;  // the loader's (or the edit's) one-line error when !ok
};

enum class DiskChange {
  Unchanged,  // the file on disk is what was loaded or last saved (or its change was kept)
  Reloaded,   // changed on disk, no unsaved edits: the document now holds the disk version
  Conflict,   // changed on disk while there are unsaved edits: call keep_mine() or reload()
  Invalid,    // changed on disk, but the loader refuses it: nothing changed; see disk_error()
};

class EffectDocument {
 public:
  // Loads and validates a file; nullptr and the loader's one-line error when it cannot.
  static std::unique_ptr<EffectDocument> open(const std::string& path, std::string& error);

  const std::string& path() const { return path_; }
  std::string name() const;                         // the effect's name: the file stem
  const std::string& text() const { return text_; }  // what save() writes
  const nlohmann::json& json() const { return json_; }
  // The definition of the current (always valid) text, and a library holding only it under
  // name(): a ParticleWorld keeps pointers into its library, so hold this shared_ptr as long
  // as a world made from it lives; a new one is made for every applied change.
  const EffectDef& def() const;
  const std::shared_ptr<const EffectLibrary>& library() const { return library_; }
  uint64_t revision() const { return revision_; }  // bumped by every applied change, undo and reload

  // Replaces the value at a JSON pointer (RFC 6901), or adds the key when its object exists
  // (objects missing on the way are added too, e.g. "/clusters/0/particles/speed" without a
  // "particles" block). Refused: the loader's message; nothing changes.
  EditResult set(const std::string& pointer, const nlohmann::json& value);
  // set() for a value being dragged: consecutive drags of the same pointer make one undo step
  // (any other edit, undo or redo ends the drag).
  EditResult drag(const std::string& pointer, const nlohmann::json& value);
  // Removes an object member or an array element (with its line when it has one to itself).
  EditResult remove(const std::string& pointer);
  // Inserts into the array at `array_pointer` before `index` (index == size appends).
  EditResult insert(const std::string& array_pointer, size_t index, const nlohmann::json& value);
  // Copies the element at `element_pointer` (its text, comments inside included) right after it.
  EditResult duplicate(const std::string& element_pointer);
  // Moves the element at index `from` of an array to index `to` (indices of the array before the move).
  EditResult move(const std::string& array_pointer, size_t from, size_t to);

  bool can_undo() const { return !undo_.empty(); }
  bool can_redo() const { return !redo_.empty(); }
  bool undo();  // false when there is nothing to undo
  bool redo();
  bool dirty() const { return text_ != disk_text_; }  // differs from the file as loaded or saved

  // Writes text() to path() atomically (core's write_file_atomic); throws InputError.
  void save();
  // Compares the file on disk with the version loaded or saved last (cheap when unchanged: one stat).
  DiskChange poll();
  // After a Conflict: keep the edits (poll() stays quiet until the file changes again) ...
  void keep_mine();
  // ... or take the disk version (an undoable change). Returns the loader's message when refused.
  EditResult reload();
  const std::string& disk_error() const { return disk_error_; }

 private:
  struct State {
    std::string text;
    nlohmann::json json;
    std::shared_ptr<const EffectLibrary> library;
  };
  EffectDocument() = default;
  // Validates new text with the loader; on success it becomes the state (old one on the undo stack).
  EditResult apply(std::string text, bool merge = false);
  bool validate(const std::string& text, State& out, std::string& error) const;
  void adopt(State s);
  State current() const;
  std::string read_disk(bool& ok);  // the file's text, remembering its time and size

  std::string path_;
  std::string text_;
  nlohmann::json json_;
  std::shared_ptr<const EffectLibrary> library_;
  uint64_t revision_ = 0;
  std::vector<State> undo_, redo_;
  std::string dragging_;                  // the pointer of the drag in progress ("" = none)
  std::string disk_text_;                 // the file as loaded or saved last
  std::string seen_disk_text_;            // the disk text poll() last reported
  std::filesystem::file_time_type disk_time_{};
  uintmax_t disk_size_ = 0;
  std::string disk_error_;
};

}  // namespace arc
