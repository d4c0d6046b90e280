// Off-screen image regression for the GoogleTest suites: compares a rendered image with the
// committed baseline Testing/Data/Baseline/<Name>.png by the structural similarity index (SSIM,
// Wang, Bovik, Sheikh & Simoncelli 2004) rather than a summed pixel difference: SSIM tolerates
// what does not change what a viewer sees (one-LSB rasteriser noise) and catches what does (a
// moved highlight, a lost term, a flipped image), whatever the size of the changed area.
//
// Debian's VTK (9.1, and 9.2 in ParaView 5.11) has only the summed metric in vtkTesting (SSIM
// arrived in VTK 9.3), so SSIM is computed here: per colour channel, Gaussian window 11 x 11 with
// sigma 1.5, C1 = (0.01 L)^2, C2 = (0.03 L)^2, L = 255, over the windows that fit in the image;
// the score is the smallest channel mean.
//
// On failure the test image and a difference image (|test - baseline| x 16) are written to
// PHONGVTK_TEST_OUTPUT_DIR (the build's Testing/Temporary) and named in the failure message.
//
// Baselines are (re)generated deliberately, never by a failing run: with the environment variable
// PHONGVTK_REGENERATE_BASELINES=1 the comparison writes the rendered image as the baseline
// instead of comparing (the test's other checks still run); scripts/regenerate-baselines.sh does
// that for chosen tests. Look at every image before committing it.
#ifndef PhongVTKImageRegression_h
#define PhongVTKImageRegression_h

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#ifndef PHONGVTK_BASELINE_DIR
#error "PHONGVTK_BASELINE_DIR must name Testing/Data/Baseline"
#endif
#ifndef PHONGVTK_TEST_OUTPUT_DIR
#error "PHONGVTK_TEST_OUTPUT_DIR must name the directory for test and difference images"
#endif

namespace phongvtk
{
namespace testing
{

/// An 8-bit image: width x height pixels of `Components` channels, rows bottom to top as VTK
/// stores them.
struct Image
{
  int Width = 0;
  int Height = 0;
  int Components = 0;
  std::vector<unsigned char> Pixels;

  unsigned char At(int x, int y, int c) const
  {
    return this->Pixels[(static_cast<size_t>(y) * this->Width + x) * this->Components + c];
  }
};

inline Image FromImageData(vtkImageData* data)
{
  Image image;
  int dims[3];
  data->GetDimensions(dims);
  auto* scalars = vtkUnsignedCharArray::SafeDownCast(data->GetPointData()->GetScalars());
  if (!scalars)
  {
    return image;
  }
  image.Width = dims[0];
  image.Height = dims[1];
  image.Components = scalars->GetNumberOfComponents();
  image.Pixels.assign(
    scalars->GetPointer(0), scalars->GetPointer(0) + scalars->GetNumberOfValues());
  return image;
}

inline vtkSmartPointer<vtkImageData> ToImageData(const Image& image)
{
  auto data = vtkSmartPointer<vtkImageData>::New();
  data->SetDimensions(image.Width, image.Height, 1);
  vtkNew<vtkUnsignedCharArray> scalars;
  scalars->SetNumberOfComponents(image.Components);
  scalars->SetNumberOfTuples(static_cast<vtkIdType>(image.Width) * image.Height);
  std::copy(image.Pixels.begin(), image.Pixels.end(), scalars->GetPointer(0));
  data->GetPointData()->SetScalars(scalars);
  return data;
}

/// The window's last frame (RGB), read without rendering again.
inline Image Capture(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ShouldRerenderOff();
  grab->Update();
  return FromImageData(grab->GetOutput());
}

inline bool WritePNG(const Image& image, const std::string& path)
{
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(ToImageData(image));
  writer->SetFileName(path.c_str());
  writer->Write();
  return writer->GetErrorCode() == 0;
}

inline bool ReadPNG(const std::string& path, Image& image)
{
  if (!std::ifstream(path).good())
  {
    return false;
  }
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  image = FromImageData(reader->GetOutput());
  return image.Width > 0;
}

/// Largest difference of any channel of any pixel, or 256 when the images do not match in shape.
inline int MaxAbsDifference(const Image& a, const Image& b)
{
  if (a.Width != b.Width || a.Height != b.Height || a.Components != b.Components)
  {
    return 256;
  }
  int largest = 0;
  for (size_t i = 0; i < a.Pixels.size(); ++i)
  {
    largest = std::max(largest, std::abs(int(a.Pixels[i]) - int(b.Pixels[i])));
  }
  return largest;
}

/// The root mean square of the channel differences of two images of the same shape, in LSB
/// (256 when their shapes differ).
inline double RMSDifference(const Image& a, const Image& b)
{
  if (a.Width != b.Width || a.Height != b.Height || a.Components != b.Components ||
    a.Pixels.empty())
  {
    return 256;
  }
  double sum = 0;
  for (size_t i = 0; i < a.Pixels.size(); ++i)
  {
    const double d = double(a.Pixels[i]) - double(b.Pixels[i]);
    sum += d * d;
  }
  return std::sqrt(sum / a.Pixels.size());
}

/// Mean SSIM of one channel of two images of the same shape (see the file comment).
inline double ChannelSSIM(const Image& a, const Image& b, int channel)
{
  constexpr int radius = 5; // 11 x 11 window
  constexpr double sigma = 1.5;
  constexpr double C1 = (0.01 * 255) * (0.01 * 255);
  constexpr double C2 = (0.03 * 255) * (0.03 * 255);
  double weights[2 * radius + 1];
  double total = 0;
  for (int i = -radius; i <= radius; ++i)
  {
    weights[i + radius] = std::exp(-0.5 * i * i / (sigma * sigma));
    total += weights[i + radius];
  }
  for (double& w : weights)
  {
    w /= total;
  }
  const int w = a.Width;
  const int h = a.Height;
  // A window larger than the image: one window, the whole image, uniformly weighted.
  if (w < 2 * radius + 1 || h < 2 * radius + 1)
  {
    double mx = 0, my = 0, sxx = 0, syy = 0, sxy = 0;
    const double n = double(w) * h;
    for (int y = 0; y < h; ++y)
    {
      for (int x = 0; x < w; ++x)
      {
        mx += a.At(x, y, channel) / n;
        my += b.At(x, y, channel) / n;
      }
    }
    for (int y = 0; y < h; ++y)
    {
      for (int x = 0; x < w; ++x)
      {
        const double dx = a.At(x, y, channel) - mx;
        const double dy = b.At(x, y, channel) - my;
        sxx += dx * dx / n;
        syy += dy * dy / n;
        sxy += dx * dy / n;
      }
    }
    return ((2 * mx * my + C1) * (2 * sxy + C2)) / ((mx * mx + my * my + C1) * (sxx + syy + C2));
  }
  // Separable Gaussian moments: horizontal pass, then vertical, over the windows that fit.
  const int ow = w - 2 * radius;
  std::vector<double> hx(size_t(ow) * h), hy(hx.size()), hxx(hx.size()), hyy(hx.size()),
    hxy(hx.size());
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < ow; ++x)
    {
      double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
      for (int k = 0; k <= 2 * radius; ++k)
      {
        const double u = a.At(x + k, y, channel);
        const double v = b.At(x + k, y, channel);
        sx += weights[k] * u;
        sy += weights[k] * v;
        sxx += weights[k] * u * u;
        syy += weights[k] * v * v;
        sxy += weights[k] * u * v;
      }
      const size_t i = size_t(y) * ow + x;
      hx[i] = sx;
      hy[i] = sy;
      hxx[i] = sxx;
      hyy[i] = syy;
      hxy[i] = sxy;
    }
  }
  double sum = 0;
  const int oh = h - 2 * radius;
  for (int y = 0; y < oh; ++y)
  {
    for (int x = 0; x < ow; ++x)
    {
      double mx = 0, my = 0, exx = 0, eyy = 0, exy = 0;
      for (int k = 0; k <= 2 * radius; ++k)
      {
        const size_t i = size_t(y + k) * ow + x;
        mx += weights[k] * hx[i];
        my += weights[k] * hy[i];
        exx += weights[k] * hxx[i];
        eyy += weights[k] * hyy[i];
        exy += weights[k] * hxy[i];
      }
      const double vx = exx - mx * mx;
      const double vy = eyy - my * my;
      const double cxy = exy - mx * my;
      sum += ((2 * mx * my + C1) * (2 * cxy + C2)) / ((mx * mx + my * my + C1) * (vx + vy + C2));
    }
  }
  return sum / (double(ow) * oh);
}

/// The smallest channel SSIM of two images (colour channels only: alpha is not compared), or 0
/// when their shapes differ.
inline double SSIM(const Image& a, const Image& b)
{
  if (a.Width != b.Width || a.Height != b.Height || a.Components != b.Components || a.Width == 0 ||
    a.Height == 0)
  {
    return 0;
  }
  double lowest = 1;
  for (int c = 0; c < std::min(a.Components, 3); ++c)
  {
    lowest = std::min(lowest, ChannelSSIM(a, b, c));
  }
  return lowest;
}

/// |test - baseline| x 16 per channel, clamped: any difference shows.
inline Image DifferenceImage(const Image& test, const Image& baseline)
{
  Image diff = test;
  if (MaxAbsDifference(test, baseline) > 255)
  {
    return diff;
  }
  for (size_t i = 0; i < diff.Pixels.size(); ++i)
  {
    const int d = std::abs(int(test.Pixels[i]) - int(baseline.Pixels[i]));
    diff.Pixels[i] = static_cast<unsigned char>(std::min(255, 16 * d));
  }
  return diff;
}

/// Compares `image` with Testing/Data/Baseline/<name>.png: passes when the SSIM is at least
/// `minimumSSIM`. See the file comment for the images written on failure and for regeneration.
/// How close an image must be to its baseline: the SSIM at least MinimumSSIM and, per channel of
/// every pixel, at most MaxLSB apart with a root mean square of at most RMSLSB.
struct Tolerance
{
  double MinimumSSIM = 0.995;
  int MaxLSB = 255;     ///< no bound unless set
  double RMSLSB = 255.; ///< no bound unless set
};

/// For shading baselines: SSIM alone cannot tell Gouraud from Phong shading of the bunny (0.9986
/// between the two, 56 LSB apart at most, RMS 0.87 LSB); 2 LSB at most and RMS 0.25 LSB can
/// (TestPhongPolyDataMapper checks that each mode fails against the others' baselines).
inline Tolerance ShadingTolerance()
{
  Tolerance t;
  t.MaxLSB = 2;
  t.RMSLSB = 0.25;
  return t;
}

inline ::testing::AssertionResult MatchesBaseline(const Image& image, const std::string& name,
  const Tolerance& tolerance, const std::string& baselineDir = PHONGVTK_BASELINE_DIR,
  const std::string& outputDir = PHONGVTK_TEST_OUTPUT_DIR);

inline ::testing::AssertionResult MatchesBaseline(const Image& image, const std::string& name,
  double minimumSSIM = 0.995, const std::string& baselineDir = PHONGVTK_BASELINE_DIR,
  const std::string& outputDir = PHONGVTK_TEST_OUTPUT_DIR)
{
  Tolerance tolerance;
  tolerance.MinimumSSIM = minimumSSIM;
  return MatchesBaseline(image, name, tolerance, baselineDir, outputDir);
}

inline ::testing::AssertionResult MatchesBaseline(const Image& image, const std::string& name,
  const Tolerance& tolerance, const std::string& baselineDir, const std::string& outputDir)
{
  const std::string baselinePath = baselineDir + "/" + name + ".png";
  const char* regenerate = std::getenv("PHONGVTK_REGENERATE_BASELINES");
  if (regenerate && std::string(regenerate) == "1")
  {
    if (!WritePNG(image, baselinePath))
    {
      return ::testing::AssertionFailure() << "could not write the baseline " << baselinePath;
    }
    return ::testing::AssertionSuccess() << "baseline written: " << baselinePath;
  }
  const std::string testPath = outputDir + "/" + name + ".png";
  const std::string diffPath = outputDir + "/" + name + ".diff.png";
  Image baseline;
  if (!ReadPNG(baselinePath, baseline))
  {
    WritePNG(image, testPath);
    return ::testing::AssertionFailure()
      << "no baseline " << baselinePath << "; the test image is " << testPath
      << ". To create it deliberately: scripts/regenerate-baselines.sh <test name regex>";
  }
  // The baseline may carry alpha or be RGB: compare the colour channels.
  if (baseline.Components != image.Components && baseline.Components >= 3 && image.Components >= 3)
  {
    Image rgb;
    rgb.Width = baseline.Width;
    rgb.Height = baseline.Height;
    rgb.Components = image.Components;
    for (int y = 0; y < baseline.Height; ++y)
    {
      for (int x = 0; x < baseline.Width; ++x)
      {
        for (int c = 0; c < image.Components; ++c)
        {
          rgb.Pixels.push_back(c < baseline.Components ? baseline.At(x, y, c) : 255);
        }
      }
    }
    baseline = rgb;
  }
  const double ssim = SSIM(image, baseline);
  const int largest = MaxAbsDifference(image, baseline);
  const double rms = RMSDifference(image, baseline);
  std::ostringstream measured;
  measured << "SSIM " << ssim << " (at least " << tolerance.MinimumSSIM << "), largest channel "
           << "difference " << largest << " LSB (at most " << tolerance.MaxLSB << "), RMS " << rms
           << " LSB (at most " << tolerance.RMSLSB << ")";
  if (ssim >= tolerance.MinimumSSIM && largest <= tolerance.MaxLSB && rms <= tolerance.RMSLSB)
  {
    return ::testing::AssertionSuccess() << name << ": " << measured.str();
  }
  WritePNG(image, testPath);
  if (largest <= 255)
  {
    WritePNG(DifferenceImage(image, baseline), diffPath);
  }
  std::ostringstream shape;
  shape << image.Width << "x" << image.Height << " vs baseline " << baseline.Width << "x"
        << baseline.Height;
  return ::testing::AssertionFailure()
    << name << ": " << measured.str() << " (" << shape.str() << ")\n  baseline:   " << baselinePath
    << "\n  test image: " << testPath << "\n  difference: " << diffPath;
}

}
}

#endif
