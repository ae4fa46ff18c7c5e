// brdfnav's SHA-1 (core/sha1.h) gives the text OpenImageIO's gave when it computed the checksums
// of a manifest (OIIO::SHA1::digest() of a file's bytes, ImageBufAlgo::computePixelHashSHA1() of
// an environment map's float RGB pixels): databases written before it still verify.
#include <brdfnav/core/sha1.h>
#include <brdfnav/renderer/env_map.h>

#include <OpenImageIO/hash.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

namespace brdfnav {
namespace {

TEST(Sha1, IsOpenImageIOsDigest) {
  std::mt19937 rng(7);
  for (std::size_t length = 0; length < 3000; length += length < 200 ? 1 : 97) {
    std::string bytes(length, '\0');
    for (char& c : bytes) c = char(rng());
    OIIO::SHA1 oiio;
    oiio.append(bytes.data(), bytes.size());
    ASSERT_EQ(sha1_hex(bytes), oiio.digest()) << length;
  }
}

TEST(Sha1, OfFloatRgbIsOpenImageIOsPixelHash) {
  std::mt19937 rng(8);
  std::uniform_real_distribution<float> radiance(0.f, 100.f);
  for (int height : {1, 3, 16, 301}) {
    const int width = 2 * height;
    std::vector<float> rgb(std::size_t(width) * height * 3);
    for (float& v : rgb) v = radiance(rng);
    const OIIO::ImageBuf buf(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT), rgb.data());
    Sha1 sha;
    sha.append(rgb.data(), rgb.size() * sizeof(float));
    ASSERT_EQ(sha.digest(), OIIO::ImageBufAlgo::computePixelHashSHA1(buf)) << height;
  }
}

// What EnvMap::pixel_sha1() records: the hash of the map's float RGB texels as loaded.
TEST(Sha1, AnEnvironmentMapsPixelHashIsTheHashOfItsTexels) {
  const EnvMap env = EnvMap::load(kDefaultEnvPath, {}, [](const std::string&) {});
  const OIIO::ImageBuf buf(OIIO::ImageSpec(env.width(), env.height(), 3, OIIO::TypeDesc::FLOAT),
                           const_cast<float*>(env.pixels().data()));
  EXPECT_EQ(env.pixel_sha1(), OIIO::ImageBufAlgo::computePixelHashSHA1(buf));
}

}  // namespace
}  // namespace brdfnav
