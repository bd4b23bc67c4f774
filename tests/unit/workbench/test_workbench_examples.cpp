// The usage examples of the workbench's edit model headers as tests (HeaderExamples.MatchTheirTests
// keeps each banner and its test the same text).
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "game/workbench/effect_document.h"
#include "game/workbench/effect_timeline.h"
#include "workbench_files.h"

namespace arc {
namespace {

TEST(WorkbenchExamples, EditAnEffect) {
  const test::ScratchDir scratch("examples_edit");
  const std::string path = scratch.copy("plasma_bolt");
  const ParticleConfig config;
  std::string error;
  std::unique_ptr<EffectDocument> doc = EffectDocument::open(path, error);  // e.g. assets/effects/plasma_bolt.json
  ASSERT_TRUE(doc) << error;
  EditResult r = doc->set("/clusters/0/emitter/rate", 120);     // r.ok, or r.message from the loader
  doc->undo();  doc->redo();
  doc->save();                                                   // atomic; throws InputError
  if (doc->poll() == DiskChange::Conflict) doc->keep_mine();     // or doc->reload()
  ParticleWorld world(config, doc->library().get());             // rebuild when revision() changes
  EXPECT_TRUE(r.ok) << r.message;
  EXPECT_NE(test::ScratchDir::read(path).find("120"), std::string::npos);
}

TEST(WorkbenchExamples, ScrubAndStep) {
  const test::ScratchDir scratch("examples_timeline");
  std::string error;
  const std::unique_ptr<EffectDocument> doc = EffectDocument::open(scratch.copy("plasma_bolt"), error);
  ASSERT_TRUE(doc) << error;
  ParticleCamera camera;
  camera.position = {0.0, 6.0, 45.0};
  const StageOptions stage;
  const ParticleWorld* world = nullptr;
  EffectTimeline t(doc->library(), doc->name(), {.motion = StageMotion::Still});
  t.scrub_to(90, camera);         // tick 90 by the catch-up path
  t.play_step(camera);            // tick 91 by normal stepping
  world = &t.world();             // for collect(); counts in t.frame_stats()
  const uint64_t tick = t.frame_stats().tick;
  // after an edit (doc->revision() changed): a timeline on the new library, at the same tick
  t = EffectTimeline(doc->library(), doc->name(), stage);  t.scrub_to(tick, camera);
  EXPECT_NE(world, nullptr);
  EXPECT_EQ(t.frame_stats().tick, tick);
}

}  // namespace
}  // namespace arc
