// The image-regression harness itself: its SSIM against values known in closed form, and what it
// writes and says when an image does not match.
#include "PhongVTKImageRegression.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <random>

namespace
{
using phongvtk::testing::Image;
using phongvtk::testing::MatchesBaseline;
using phongvtk::testing::SSIM;

constexpr double C1 = (0.01 * 255) * (0.01 * 255);
constexpr double C2 = (0.03 * 255) * (0.03 * 255);

Image Filled(int width, int height, const std::function<int(int, int, int)>& value)
{
  Image image;
  image.Width = width;
  image.Height = height;
  image.Components = 3;
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        image.Pixels.push_back(static_cast<unsigned char>(value(x, y, c)));
      }
    }
  }
  return image;
}

// Smooth structure with edges, like a rendering: rings and a bar.
Image Scene(int shift = 0)
{
  return Filled(64, 48,
    [shift](int x, int y, int c)
    {
      const double r = std::hypot(x - 30 - shift, y - 24);
      int v = static_cast<int>(127 + 100 * std::cos(r / 3.0));
      if (x > 50 && x < 56)
      {
        v = 240;
      }
      return std::min(255, std::max(0, v - 20 * c));
    });
}

TEST(ImageRegression, IdenticalImagesHaveSSIMOne)
{
  const Image a = Scene();
  EXPECT_NEAR(SSIM(a, a), 1.0, 1e-12);
}

TEST(ImageRegression, ConstantImagesHaveTheLuminanceTermOnly)
{
  // No variance: SSIM = (2 p q + C1) / (p^2 + q^2 + C1), in every window.
  const int p = 100;
  const int q = 130;
  const Image a = Filled(40, 30, [p](int, int, int) { return p; });
  const Image b = Filled(40, 30, [q](int, int, int) { return q; });
  EXPECT_NEAR(SSIM(a, b), (2.0 * p * q + C1) / (double(p) * p + double(q) * q + C1), 1e-12);
}

TEST(ImageRegression, InvertedCheckerboardIsAnticorrelated)
{
  // Smaller than the window: one uniform window. Means 127.5, variances s2 = 127.5^2,
  // covariance -s2: SSIM = (C2 - 2 s2) / (2 s2 + C2).
  const Image a = Filled(4, 4, [](int x, int y, int) { return (x + y) % 2 ? 255 : 0; });
  const Image b = Filled(4, 4, [](int x, int y, int) { return (x + y) % 2 ? 0 : 255; });
  const double s2 = 127.5 * 127.5;
  EXPECT_NEAR(SSIM(a, b), (C2 - 2 * s2) / (2 * s2 + C2), 1e-12);
}

TEST(ImageRegression, ToleratesOneLSBNoiseButNotMovedStructure)
{
  const Image a = Scene();
  Image noisy = a;
  std::mt19937 random(7);
  for (unsigned char& v : noisy.Pixels)
  {
    const int d = static_cast<int>(random() % 3) - 1;
    v = static_cast<unsigned char>(std::min(255, std::max(0, v + d)));
  }
  EXPECT_GT(SSIM(a, noisy), 0.995);
  EXPECT_LT(SSIM(a, Scene(3)), 0.9);
}

TEST(ImageRegression, DifferentShapesNeverMatch)
{
  EXPECT_EQ(SSIM(Scene(), Filled(10, 10, [](int, int, int) { return 0; })), 0.0);
}

bool Exists(const std::string& path)
{
  return std::ifstream(path).good();
}

TEST(ImageRegression, AMismatchWritesTheTestAndDifferenceImagesAndNamesThem)
{
  unsetenv("PHONGVTK_REGENERATE_BASELINES"); // this test is about comparing
  const std::string dir = PHONGVTK_TEST_OUTPUT_DIR;
  const std::string name = "ImageRegressionMismatch";
  // A baseline directory of its own in the test output.
  const std::string baselineDir = dir + "/ImageRegressionBaselines";
  std::filesystem::create_directories(baselineDir);
  std::filesystem::remove(dir + "/" + name + ".png");
  std::filesystem::remove(dir + "/" + name + ".diff.png");
  ASSERT_TRUE(phongvtk::testing::WritePNG(Scene(), baselineDir + "/" + name + ".png"));

  EXPECT_TRUE(MatchesBaseline(Scene(), name, 0.995, baselineDir, dir));
  const ::testing::AssertionResult moved = MatchesBaseline(Scene(3), name, 0.995, baselineDir, dir);
  ASSERT_FALSE(moved);
  const std::string message = moved.message();
  EXPECT_NE(message.find(dir + "/" + name + ".png"), std::string::npos) << message;
  EXPECT_NE(message.find(dir + "/" + name + ".diff.png"), std::string::npos) << message;
  EXPECT_NE(message.find("SSIM"), std::string::npos) << message;
  ASSERT_TRUE(Exists(dir + "/" + name + ".png"));
  ASSERT_TRUE(Exists(dir + "/" + name + ".diff.png"));
  // The difference image is |test - baseline| x 16.
  Image diff;
  ASSERT_TRUE(phongvtk::testing::ReadPNG(dir + "/" + name + ".diff.png", diff));
  const Image a = Scene(3);
  const Image b = Scene();
  for (size_t i = 0; i < diff.Pixels.size(); i += 97)
  {
    EXPECT_EQ(diff.Pixels[i], std::min(255, 16 * std::abs(int(a.Pixels[i]) - int(b.Pixels[i]))));
  }
}

TEST(ImageRegression, AMissingBaselineFailsAndSaysHowToCreateIt)
{
  unsetenv("PHONGVTK_REGENERATE_BASELINES");
  const std::string dir = PHONGVTK_TEST_OUTPUT_DIR;
  const ::testing::AssertionResult missing =
    MatchesBaseline(Scene(), "NoSuchBaseline", 0.995, dir + "/nowhere", dir);
  ASSERT_FALSE(missing);
  EXPECT_NE(std::string(missing.message()).find("regenerate-baselines.sh"), std::string::npos);
  EXPECT_TRUE(Exists(dir + "/NoSuchBaseline.png"));
}
}
