// ImageWriter: the builder's image files written on a thread of their own while the next unit
// of work renders (precompute_job.cpp).
#pragma once

#include <brdfnav/renderer/image_output.h>

#include <filesystem>
#include <functional>
#include <future>
#include <utility>
#include <vector>

namespace brdfnav {

// An image to write: a database's images are halves (ExrPixels::half_raw).
struct PendingFile {
  Image image;
  std::filesystem::path path;
  ImageMetadata metadata;
  ExrPixels pixels = ExrPixels::half_raw;
};

// Writes each unit's images (as each PendingFile says) on a thread of its own while the next unit
// renders. One unit in flight; its errors are rethrown by the next write() or by finish().
// `written` is called once per file written, on the caller's thread, as the progress observer
// expects. If a render fails, destruction waits for the write in flight (std::async's future).
class ImageWriter {
 public:
  explicit ImageWriter(std::function<void()> written) : written_(std::move(written)) {}

  void write(std::vector<PendingFile> files) {
    finish();
    count_ = files.size();
    in_flight_ = std::async(std::launch::async, [files = std::move(files)] {
      for (const PendingFile& f : files) write_exr(f.image, f.path, f.metadata, f.pixels);
    });
  }
  void finish() {
    if (!in_flight_.valid()) return;
    in_flight_.get();
    for (; count_ > 0; --count_) written_();
  }

 private:
  std::function<void()> written_;
  std::future<void> in_flight_;
  std::size_t count_ = 0;
};

}  // namespace brdfnav
