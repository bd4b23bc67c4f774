// The workbench's edit model: edits validated by the game's loader, undo/redo, comment-keeping
// save, and the disk watch.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "game/workbench/effect_document.h"
#include "tests/unit/workbench/workbench_files.h"
#include "core/data_root.h"

namespace arc {
namespace {

using test::ScratchDir;
using nlohmann::json;

std::unique_ptr<EffectDocument> open_ok(const std::string& path) {
  std::string error;
  auto doc = EffectDocument::open(path, error);
  EXPECT_TRUE(doc) << error;
  return doc;
}

TEST(EffectDocument, OpenRefusesABadFileWithTheLoadersLine) {
  ScratchDir dir("open_bad");
  const std::string path = dir.write("bad.json", "{\n  \"clusters\": [ { \"sprite\": \"nope\", \"animation\": {}, \"emitter\": { \"burst\": 1 } } ]\n}\n");
  std::string error;
  EXPECT_FALSE(EffectDocument::open(path, error));
  EXPECT_EQ(error.rfind(path + ":2:", 0), 0u) << error;
  EXPECT_NE(error.find("'clusters[0].sprite' must be one of"), std::string::npos) << error;
  EXPECT_FALSE(EffectDocument::open(dir.write("x.txt", "") + "_missing", error));
  EXPECT_NE(error.find("cannot open"), std::string::npos) << error;
}

TEST(EffectDocument, SetAppliesAValidEditToTheDefinition) {
  ScratchDir dir("set");
  auto doc = open_ok(dir.write("puff.json", test::kCommentedEffect));
  const uint64_t rev = doc->revision();
  auto old_library = doc->library();
  EXPECT_EQ(doc->def().clusters[0].emitter.burst, 10u);
  const EditResult r = doc->set("/clusters/0/emitter/burst", 25);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(doc->def().clusters[0].emitter.burst, 25u);
  EXPECT_EQ(doc->json()["clusters"][0]["emitter"]["burst"], 25);
  EXPECT_GT(doc->revision(), rev);
  EXPECT_NE(doc->library(), old_library);  // a world built on the old one stays valid
  EXPECT_EQ(old_library->get("puff").clusters[0].emitter.burst, 10u);
  EXPECT_TRUE(doc->dirty());
}

TEST(EffectDocument, RefusedEditChangesNothingAndGivesTheLoadersMessage) {
  ScratchDir dir("refuse");
  const std::string path = dir.write("puff.json", test::kCommentedEffect);
  auto doc = open_ok(path);
  const std::string text = doc->text();
  const uint64_t rev = doc->revision();
  EditResult r = doc->set("/clusters/0/curves/alpha/1/1", 2.0);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.message.rfind(path + ":12:", 0), 0u) << r.message;
  EXPECT_NE(r.message.find("'clusters[0].curves.alpha' values must be in [0, 1], got 2"), std::string::npos) << r.message;
  r = doc->set("/clusters/0/emitter/shape", "teapot");
  EXPECT_NE(r.message.find("'clusters[0].emitter.shape' must be one of \"point\""), std::string::npos) << r.message;
  r = doc->set("/clusters/0/emitter/burts", 3);
  EXPECT_NE(r.message.find("unknown key 'burts'"), std::string::npos) << r.message;
  r = doc->remove("/clusters/0/sprite");
  EXPECT_FALSE(r.ok);
  r = doc->set("/clusters/7/name", "x");
  EXPECT_NE(r.message.find("no value at '/clusters/7/name'"), std::string::npos) << r.message;
  EXPECT_EQ(doc->text(), text);
  EXPECT_EQ(doc->revision(), rev);
  EXPECT_FALSE(doc->dirty());
  EXPECT_FALSE(doc->can_undo());
}

TEST(EffectDocument, UndoAndRedoCoverEveryKindOfEdit) {
  ScratchDir dir("undo");
  auto doc = open_ok(dir.write("puff.json", test::kCommentedEffect));
  std::vector<std::string> texts{doc->text()};
  ASSERT_TRUE(doc->set("/clusters/0/particles/lifetime", json::array({0.4, 0.9})).ok);
  texts.push_back(doc->text());
  ASSERT_TRUE(doc->duplicate("/clusters/1").ok);
  texts.push_back(doc->text());
  ASSERT_TRUE(doc->set("/clusters/2/name", "sparks2").ok);
  texts.push_back(doc->text());
  ASSERT_TRUE(doc->move("/clusters", 2, 0).ok);
  texts.push_back(doc->text());
  ASSERT_TRUE(doc->remove("/clusters/2").ok);
  texts.push_back(doc->text());
  ASSERT_TRUE(doc->insert("/clusters/1/curves/alpha", 1, json::array({0.5, 0.7})).ok);
  texts.push_back(doc->text());
  EXPECT_EQ(doc->def().clusters.size(), 2u);
  EXPECT_EQ(doc->def().clusters[0].name, "sparks2");
  for (size_t i = texts.size() - 1; i > 0; --i) {
    ASSERT_TRUE(doc->can_undo());
    EXPECT_TRUE(doc->undo());
    EXPECT_EQ(doc->text(), texts[i - 1]) << "after undoing edit " << i;
  }
  EXPECT_FALSE(doc->can_undo());
  EXPECT_FALSE(doc->undo());
  EXPECT_FALSE(doc->dirty());
  for (size_t i = 1; i < texts.size(); ++i) {
    EXPECT_TRUE(doc->redo());
    EXPECT_EQ(doc->text(), texts[i]);
  }
  EXPECT_FALSE(doc->can_redo());
  doc->undo();
  ASSERT_TRUE(doc->set("/description", "new").ok);  // a new edit drops the redo history
  EXPECT_FALSE(doc->can_redo());
}

TEST(EffectDocument, ADragIsOneUndoStep) {
  ScratchDir dir("drag");
  auto doc = open_ok(dir.write("puff.json", test::kCommentedEffect));
  const std::string original = doc->text();
  ASSERT_TRUE(doc->set("/description", "before the drag").ok);
  const std::string before = doc->text();
  ASSERT_TRUE(doc->drag("/clusters/0/emitter/burst", 10).ok);  // no change yet: no step
  for (int burst : {11, 14, 20, 26}) ASSERT_TRUE(doc->drag("/clusters/0/emitter/burst", burst).ok);
  EXPECT_FALSE(doc->drag("/clusters/0/emitter/burst", -1).ok);  // refused mid-drag: the drag goes on
  ASSERT_TRUE(doc->drag("/clusters/0/emitter/burst", 30).ok);
  ASSERT_TRUE(doc->drag("/clusters/0/particles/lifetime", 0.7).ok);  // another field: a new step
  ASSERT_TRUE(doc->drag("/clusters/0/particles/lifetime", 0.8).ok);
  EXPECT_EQ(doc->def().clusters[0].emitter.burst, 30u);
  ASSERT_TRUE(doc->undo());
  EXPECT_EQ(doc->def().clusters[0].particles.lifetime.max, 0.5);
  EXPECT_EQ(doc->def().clusters[0].emitter.burst, 30u);
  ASSERT_TRUE(doc->undo());
  EXPECT_EQ(doc->text(), before);
  ASSERT_TRUE(doc->undo());
  EXPECT_EQ(doc->text(), original);
  EXPECT_FALSE(doc->can_undo());
}

TEST(EffectDocument, SavingAnUntouchedFileWritesTheSameBytesForEveryEffect) {
  ScratchDir dir("untouched");
  for (const auto& e : std::filesystem::directory_iterator(arc::data_root() + "/assets/effects")) {
    if (e.path().extension() != ".json") continue;
    const std::string path = dir.copy(e.path().stem().string());
    const std::string before = ScratchDir::read(path);
    auto doc = open_ok(path);
    ASSERT_TRUE(doc);
    doc->save();
    EXPECT_EQ(ScratchDir::read(path), before) << path;
  }
}

TEST(EffectDocument, ChangingOneNumberChangesOnlyItsBytes) {
  ScratchDir dir("one_number");
  const std::string path = dir.copy("ship_explosion");
  const std::string before = ScratchDir::read(path);
  auto doc = open_ok(path);
  size_t i = 0;
  while (!doc->json()["clusters"][i]["animation"].contains("growth")) ++i;
  const double old_growth = doc->json()["clusters"][i]["animation"]["growth"].get<double>();
  ASSERT_TRUE(doc->set("/clusters/" + std::to_string(i) + "/animation/growth", old_growth + 0.25).ok);
  doc->save();
  const std::string after = ScratchDir::read(path);
  size_t head = 0;
  while (head < before.size() && head < after.size() && before[head] == after[head]) ++head;
  size_t tail = 0;
  while (tail < before.size() - head && tail < after.size() - head &&
         before[before.size() - 1 - tail] == after[after.size() - 1 - tail])
    ++tail;
  const std::string old_bytes = before.substr(head, before.size() - head - tail);
  const std::string new_bytes = after.substr(head, after.size() - head - tail);
  EXPECT_LE(old_bytes.size(), 4u) << old_bytes;  // only digits of the one number differ
  EXPECT_EQ(json::parse(after, nullptr, true, true)["clusters"][i]["animation"]["growth"].get<double>(), old_growth + 0.25);
  for (char c : old_bytes + new_bytes) EXPECT_TRUE(std::isdigit(static_cast<unsigned char>(c)) || c == '.') << c;
}

TEST(EffectDocument, CommentsSurviveEditsAndSave) {
  ScratchDir dir("comments");
  const std::string path = dir.write("puff.json", test::kCommentedEffect);
  auto doc = open_ok(path);
  ASSERT_TRUE(doc->set("/clusters/0/emitter/burst", 12).ok);
  ASSERT_TRUE(doc->set("/clusters/0/soft_edge", "linear").ok);
  ASSERT_TRUE(doc->remove("/clusters/1/emitter/duration").ok);
  ASSERT_TRUE(doc->duplicate("/clusters/0").ok);
  doc->save();
  const std::string saved = ScratchDir::read(path);
  for (const char* comment : {"// A test effect: comments must survive every save.", "// trailing comment", "/* a block comment */"})
    EXPECT_NE(saved.find(comment), std::string::npos) << comment << "\n" << saved;
  EXPECT_FALSE(doc->dirty());
}

TEST(EffectDocument, NewKeysTakeTheFilesOwnIndentation) {
  ScratchDir dir("indent");
  auto doc = open_ok(dir.write("puff.json", test::kCommentedEffect));
  ASSERT_TRUE(doc->set("/clusters/1/lifetime", 2).ok);           // a block laid out one key per line
  ASSERT_TRUE(doc->set("/clusters/1/emitter/burst", 4).ok);      // an inline block
  ASSERT_TRUE(doc->set("/clusters/1/particles/size", json::array({0.2, 0.4})).ok);  // a missing block
  const std::string& t = doc->text();
  EXPECT_NE(t.find("      \"emitter\": { \"rate\": 30, \"duration\": 0.2, \"burst\": 4 },\n      \"lifetime\": 2,\n"
                   "      \"particles\": { \"size\": [0.2, 0.4] }\n    }"),
            std::string::npos)
      << t;
}

TEST(EffectDocument, ANewClusterIsWrittenInTheFilesLayout) {
  ScratchDir dir("new_cluster");
  auto doc = open_ok(dir.write("puff.json", test::kCommentedEffect));
  const json cluster = {{"name", "glow"}, {"sprite", "glow"}, {"animation", {{"type", "linear"}}}, {"emitter", {{"burst", 3}}}};
  const EditResult r = doc->insert("/clusters", 2, cluster);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(doc->def().clusters.size(), 3u);
  EXPECT_NE(doc->text().find("\"duration\": 0.2 }\n    },\n    {\n      \"animation\": { \"type\": \"linear\" },\n"
                             "      \"emitter\": { \"burst\": 3 },\n      \"name\": \"glow\",\n      \"sprite\": \"glow\"\n    }\n  ]"),
            std::string::npos)
      << doc->text();
}

TEST(EffectDocument, RemovedKeysAndElementsGoWithTheirLines) {
  ScratchDir dir("remove");
  auto doc = open_ok(dir.write("puff.json", test::kCommentedEffect));
  ASSERT_TRUE(doc->remove("/description").ok);
  EXPECT_EQ(doc->text().find("test puff"), std::string::npos);
  EXPECT_NE(doc->text().find("{\n  \"clusters\": ["), std::string::npos) << doc->text();
  ASSERT_TRUE(doc->remove("/clusters/0").ok);
  EXPECT_NE(doc->text().find("  \"clusters\": [\n    {\n      \"name\": \"sparks\""), std::string::npos) << doc->text();
  ASSERT_TRUE(doc->duplicate("/clusters/0").ok);
  ASSERT_TRUE(doc->remove("/clusters/1").ok);  // the last element: the comma before it goes too
  EXPECT_NE(doc->text().find("\"duration\": 0.2 }\n    }\n  ]\n}\n"), std::string::npos) << doc->text();
}

TEST(EffectDocument, ARefusedEditLeavesTheFileUntouched) {
  ScratchDir dir("bad_edit");
  const std::string path = dir.write("puff.json", test::kCommentedEffect);
  auto doc = open_ok(path);
  EXPECT_FALSE(doc->set("/clusters/0/particles/lifetime", -1).ok);
  EXPECT_FALSE(doc->set("/clusters", json::array()).ok);
  doc->save();
  EXPECT_EQ(ScratchDir::read(path), test::kCommentedEffect);
}

// Writes a file so that its modification time surely differs from the last one seen.
void rewrite(const std::string& path, const std::string& text) {
  const auto before = std::filesystem::last_write_time(path);
  std::ofstream(path, std::ios::binary) << text;
  std::filesystem::last_write_time(path, before + std::chrono::seconds(1));
}

TEST(EffectDocument, PollReloadsAFileChangedOnDiskWhenThereAreNoEdits) {
  ScratchDir dir("reload");
  const std::string path = dir.write("puff.json", test::kCommentedEffect);
  auto doc = open_ok(path);
  EXPECT_EQ(doc->poll(), DiskChange::Unchanged);
  std::string changed = test::kCommentedEffect;
  changed.replace(changed.find("\"burst\": 10"), 11, "\"burst\": 40");
  rewrite(path, changed);
  EXPECT_EQ(doc->poll(), DiskChange::Reloaded);
  EXPECT_EQ(doc->def().clusters[0].emitter.burst, 40u);
  EXPECT_FALSE(doc->dirty());
  EXPECT_EQ(doc->poll(), DiskChange::Unchanged);
  rewrite(path, "{ \"clusters\": [] }");
  EXPECT_EQ(doc->poll(), DiskChange::Invalid);
  EXPECT_NE(doc->disk_error().find("'clusters' must list at least one cluster"), std::string::npos) << doc->disk_error();
  EXPECT_EQ(doc->def().clusters[0].emitter.burst, 40u);
}

TEST(EffectDocument, PollReportsAConflictWhenThereAreUnsavedEdits) {
  ScratchDir dir("conflict");
  const std::string path = dir.write("puff.json", test::kCommentedEffect);
  auto doc = open_ok(path);
  ASSERT_TRUE(doc->set("/clusters/0/emitter/burst", 11).ok);
  std::string changed = test::kCommentedEffect;
  changed.replace(changed.find("\"burst\": 10"), 11, "\"burst\": 40");
  rewrite(path, changed);
  EXPECT_EQ(doc->poll(), DiskChange::Conflict);
  EXPECT_EQ(doc->def().clusters[0].emitter.burst, 11u);
  doc->keep_mine();
  EXPECT_EQ(doc->poll(), DiskChange::Unchanged);
  EXPECT_TRUE(doc->dirty());
  ASSERT_TRUE(doc->reload().ok);  // the user changes their mind: take the disk version
  EXPECT_EQ(doc->def().clusters[0].emitter.burst, 40u);
  EXPECT_FALSE(doc->dirty());
  EXPECT_TRUE(doc->undo());  // and the edits are one undo away
  EXPECT_EQ(doc->def().clusters[0].emitter.burst, 11u);
}

}  // namespace
}  // namespace arc
