// SHA-1: the FIPS 180 test vectors, and the same digest however a message is cut into appends.
#include <brdfnav/core/sha1.h>

#include <gtest/gtest.h>

#include <string>

namespace brdfnav {
namespace {

TEST(Sha1, FipsVectors) {
  EXPECT_EQ(sha1_hex(""), "DA39A3EE5E6B4B0D3255BFEF95601890AFD80709");
  EXPECT_EQ(sha1_hex("abc"), "A9993E364706816ABA3E25717850C26C9CD0D89D");
  EXPECT_EQ(sha1_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "84983E441C3BD26EBAAE4AA1F95129E5E54670F1");
  EXPECT_EQ(sha1_hex(std::string(1000000, 'a')), "34AA973CD4C4DAA4F61EEB2BDBAD27316534016F");
}

// Lengths around the padding's boundaries (55, 56, 63, 64 bytes), appended whole and in pieces
// of every size from 1 to 70 bytes.
TEST(Sha1, AppendsInPiecesGiveTheWholeMessagesDigest) {
  for (std::size_t length : {0, 1, 55, 56, 57, 63, 64, 65, 119, 120, 128, 1000}) {
    std::string message(length, '\0');
    for (std::size_t i = 0; i < length; ++i) message[i] = char(i * 37 + 11);
    const std::string whole = sha1_hex(message);
    for (std::size_t piece = 1; piece <= 70; ++piece) {
      Sha1 sha;
      for (std::size_t at = 0; at < length; at += piece)
        sha.append(message.substr(at, std::min(piece, length - at)));
      ASSERT_EQ(sha.digest(), whole) << length << " in pieces of " << piece;
    }
  }
}

TEST(Sha1, DigestLeavesTheMessageOpen) {
  Sha1 sha;
  sha.append("ab");
  EXPECT_EQ(sha.digest(), sha1_hex("ab"));
  sha.append("c");
  EXPECT_EQ(sha.digest(), sha1_hex("abc"));
}

}  // namespace
}  // namespace brdfnav
