// SHA-1 (FIPS 180-4) of bytes, as the 40 upper-case hex digits a database's manifest records for
// its files and its environment map's pixels (the text OpenImageIO's SHA1::digest() gave when it
// computed them, so databases written before stay valid).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace brdfnav {

class Sha1 {
 public:
  Sha1();
  // Appends `size` bytes at `data` to the message.
  void append(const void* data, std::size_t size);
  void append(std::string_view text) { append(text.data(), text.size()); }
  // The digest of everything appended so far, as 40 upper-case hex digits. The object can still
  // be appended to (the digest is computed on a copy of the state).
  std::string digest() const;

 private:
  void block(const std::uint8_t* bytes);

  std::array<std::uint32_t, 5> state_;
  std::array<std::uint8_t, 64> buffer_{};
  std::size_t buffered_ = 0;
  std::uint64_t length_ = 0;  // bytes appended
};

// The digest of `data`.
std::string sha1_hex(std::string_view data);

}  // namespace brdfnav
