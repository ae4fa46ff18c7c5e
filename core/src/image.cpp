#include <brdfnav/core/image.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace brdfnav {

void check_same_shape(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height)
    throw ImageError("image sizes differ: " + std::to_string(a.width) + "x" +
                     std::to_string(a.height) + " and " + std::to_string(b.width) + "x" +
                     std::to_string(b.height));
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      if (a.covered(x, y) != b.covered(x, y))
        throw ImageError("image masks (alpha) differ, first at pixel (" + std::to_string(x) + ", " +
                         std::to_string(y) + ")");
}

Image compose(const Image& diffuse, const Image& specular, const Rgb& rho_d, const Rgb& rho_s) {
  check_same_shape(diffuse, specular);
  Image out(diffuse.width, diffuse.height);
  for (std::size_t i = 0; i < out.rgba.size(); i += 4) {
    for (int c = 0; c < 3; ++c)
      out.rgba[i + c] =
          static_cast<float>(rho_d[c] * diffuse.rgba[i + c] + rho_s[c] * specular.rgba[i + c]);
    out.rgba[i + 3] = diffuse.rgba[i + 3];
  }
  return out;
}

double image_distance(const Image& a, const Image& b) {
  check_same_shape(a, b);
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
    if (a.rgba[i + 3] <= 0.5f) continue;
    for (int c = 0; c < 3; ++c) {
      const double d = std::cbrt(double(a.rgba[i + c])) - std::cbrt(double(b.rgba[i + c]));
      sum += d * d;
    }
    count += 3;
  }
  if (count == 0) throw ImageError("the images cover no pixel");
  return std::sqrt(sum / count);
}

namespace {

// Lanczos-3: sinc(x) sinc(x / 3) on |x| < 3.
double lanczos3(double x) {
  x = std::abs(x);
  if (x < 1e-9) return 1;
  if (x >= 3) return 0;
  const double px = kPi * x;
  return 3 * std::sin(px) * std::sin(px / 3) / (px * px);
}

// Blackman-Harris (4 terms) on |x| < 1.5.
double blackman_harris(double x) {
  if (std::abs(x) >= 1.5) return 0;
  const double t = 2 * kPi * (x / 1.5 + 1) / 2;
  return 0.35875 - 0.48829 * std::cos(t) + 0.14128 * std::cos(2 * t) - 0.01168 * std::cos(3 * t);
}

// The weights of one axis from `in` samples to `out`: for output sample i, the source indices
// from first[i] on and their normalised weights.
struct ResampleWeights {
  std::vector<int> first, count;
  std::vector<std::vector<float>> weights;
};

ResampleWeights resample_weights(int in, int out) {
  const double ratio = double(out) / in;
  const bool enlarging = ratio > 1;
  const double scale = enlarging ? 1 : 1 / ratio;  // widen the filter when shrinking
  const double support = (enlarging ? 1.5 : 3) * scale;
  ResampleWeights w;
  for (int i = 0; i < out; ++i) {
    const double centre = (i + 0.5) / ratio;  // in source pixel units, centres at k + 0.5
    const int lo = int(std::floor(centre - support)), hi = int(std::ceil(centre + support));
    std::vector<double> raw;
    double sum = 0;
    for (int k = lo; k <= hi; ++k) {
      const double x = (k + 0.5 - centre) / scale;
      const double v = enlarging ? blackman_harris(x) : lanczos3(x);
      raw.push_back(v);
      sum += v;
    }
    // Clamp to the edge: the weights of samples beyond it go to the edge sample.
    std::vector<float> folded(in, 0.f);
    for (int k = lo; k <= hi; ++k) folded[std::clamp(k, 0, in - 1)] += float(raw[k - lo] / sum);
    int first = 0, last = in - 1;
    while (first < last && folded[first] == 0.f) ++first;
    while (last > first && folded[last] == 0.f) --last;
    w.first.push_back(first);
    w.count.push_back(last - first + 1);
    w.weights.emplace_back(folded.begin() + first, folded.begin() + last + 1);
  }
  return w;
}

}  // namespace

Image resample(const Image& image, int width, int height) {
  if (image.width <= 0 || image.height <= 0 || width <= 0 || height <= 0)
    throw ImageError("cannot resample a " + std::to_string(image.width) + "x" +
                     std::to_string(image.height) + " image to " + std::to_string(width) + "x" +
                     std::to_string(height));
  if (width == image.width && height == image.height) return image;
  // Rows first (image.height x width), then columns, accumulated in double.
  const ResampleWeights across = resample_weights(image.width, width);
  const ResampleWeights down = resample_weights(image.height, height);
  std::vector<double> rows(static_cast<std::size_t>(image.height) * width * 4, 0.0);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < width; ++x) {
      double* out = &rows[4 * (static_cast<std::size_t>(y) * width + x)];
      for (int k = 0; k < across.count[x]; ++k) {
        const float* in = image.pixel(across.first[x] + k, y);
        const double w = across.weights[x][k];
        for (int c = 0; c < 4; ++c) out[c] += w * in[c];
      }
    }
  Image out(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      double sum[4] = {0, 0, 0, 0};
      for (int k = 0; k < down.count[y]; ++k) {
        const double* in = &rows[4 * (static_cast<std::size_t>(down.first[y] + k) * width + x)];
        const double w = down.weights[y][k];
        for (int c = 0; c < 4; ++c) sum[c] += w * in[c];
      }
      for (int c = 0; c < 4; ++c) out.pixel(x, y)[c] = float(sum[c]);
    }
  return out;
}

}  // namespace brdfnav
