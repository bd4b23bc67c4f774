// assets/screenshot_writer.cpp — numbered PNG screenshots encoded and written in the background.
#include "assets/screenshot_writer.h"

#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <utility>

namespace arc {

ScreenshotWriter::ScreenshotWriter(std::string folder, std::string prefix)
    : folder_(std::move(folder)), prefix_(std::move(prefix)) {}

ScreenshotWriter::~ScreenshotWriter() {
  for (Job& job : jobs_) job.result.wait();
}

std::string ScreenshotWriter::next_path() const {
  for (int i = 1;; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "_%04d.png", i);
    const std::string path = (std::filesystem::path(folder_) / (prefix_ + name)).string();
    std::error_code ec;
    bool taken = std::filesystem::exists(path, ec) || ec;  // a name that cannot be checked is not taken
    for (const Job& job : jobs_) taken = taken || job.path == path;
    if (!taken) return path;
  }
}

std::string ScreenshotWriter::save(Image image) {
  std::error_code ec;  // a folder that cannot be made is reported by the write
  std::filesystem::create_directories(folder_, ec);
  const std::string path = next_path();
  jobs_.push_back({path, std::async(std::launch::async, [path, img = std::move(image)]() -> std::string {
                     try {
                       save_image(path, img);
                       return "";
                     } catch (const std::exception& e) {
                       return e.what();
                     }
                   })});
  return path;
}

std::vector<ScreenshotWriter::Done> ScreenshotWriter::finished() {
  std::vector<Done> done;
  for (size_t i = 0; i < jobs_.size();) {
    if (jobs_[i].result.wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
      ++i;
      continue;
    }
    done.push_back({jobs_[i].path, jobs_[i].result.get()});
    jobs_.erase(jobs_.begin() + std::ptrdiff_t(i));
  }
  return done;
}

std::vector<ScreenshotWriter::Done> ScreenshotWriter::wait() {
  for (Job& job : jobs_) job.result.wait();
  return finished();
}

}  // namespace arc
