// A read-only memory map of a whole file: what the database maps instead of reading, so that a
// process holds only the pages its queries touch (the embedding of a dense grid is ~100 MB, of
// which a navigation session reads a few nodes' columns).
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>

namespace brdfnav::db {

class MappedFile {
 public:
  // Throws DatabaseError naming the file when it cannot be opened or mapped. An empty file maps
  // to no bytes.
  explicit MappedFile(const std::filesystem::path& path);
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  std::span<const std::byte> bytes() const { return {data_, size_}; }
  // Unmaps the pages this process has touched (MADV_DONTNEED): they stay in the page cache, and
  // a later read maps them again with the same contents (the map is read-only and private).
  void release_pages() const;

 private:
  const std::byte* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace brdfnav::db
