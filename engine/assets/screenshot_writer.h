// assets/screenshot_writer.h — numbered PNG screenshots encoded and written in the background.
//
// Encoding a full-screen PNG takes several frames' time, so on the frame's thread every F12 would
// be a visible hitch. The frame's thread only reads the pixels and hands them over; a worker
// thread per shot encodes and writes (save_image: checked and atomic). Each shot takes the first
// free number in the folder, counting the shots still being written, so quick presses never share
// a name. The destructor waits for every shot (nothing is lost at exit).
//
// Example, compiled as AssetExamples.ShotsInTheBackground in tests/unit/assets/test_asset_examples.cpp:
//   ScreenshotWriter shots("out/screenshots", "arcfire");
//   std::string path = shots.save(frame);            // out/screenshots/arcfire_0001.png
//   for (const ScreenshotWriter::Done& d : shots.finished())
//     notices.push_back(d.error.empty() ? "saved " + d.path : d.error);
#pragma once
#include <future>
#include <string>
#include <vector>

#include "assets/image.h"

namespace arc {

class ScreenshotWriter {
 public:
  ScreenshotWriter(std::string folder, std::string prefix);
  ~ScreenshotWriter();  // waits for the shots still being written
  ScreenshotWriter(const ScreenshotWriter&) = delete;
  ScreenshotWriter& operator=(const ScreenshotWriter&) = delete;

  // Starts writing `image` as <folder>/<prefix>_NNNN.png (the folder made when missing) and
  // returns that path.
  std::string save(Image image);
  struct Done {
    std::string path;
    std::string error;  // empty when written; else one line: the file and what went wrong
  };
  // The shots written (or failed) since the last call, oldest first; never blocks.
  std::vector<Done> finished();
  // Waits for every shot still being written and returns them, as finished().
  std::vector<Done> wait();
  int pending() const { return int(jobs_.size()); }

 private:
  struct Job {
    std::string path;
    std::future<std::string> result;  // the error line, empty on success
  };
  std::string next_path() const;
  std::string folder_, prefix_;
  std::vector<Job> jobs_;
};

}  // namespace arc
