// The exact volume sign: zero where four points lie exactly in one plane although their
// products need more bits than a double has, the sign of a perturbation far below the
// floating-point determinant's rounding, and a refusal where a difference is not exact.
#include <gtest/gtest.h>

#include "fdh/orient3d_exact.hpp"

namespace fdh {
namespace {

// Four points of the plane z = s (x + y), s = 1 + 2^-30, with a and b of 22 bits: every
// coordinate and difference is an exact double, the volume's products need about 75 bits.
constexpr double kS = 1 + 0x1p-30, kA = 3145729, kB = 2621443;
const Vec3 kP0{0, 0, 0}, kP1{kA, 0, kA*kS}, kP2{0, kB, kB*kS};

int volume_sign(const Vec3& p3) {
  int sign = 7;
  EXPECT_TRUE(exact_volume_sign(kP0, kP1, kP2, p3, sign));
  return sign;
}

TEST(ExactVolumeSign, CoplanarBeyondDoublePrecisionIsZero) {
  EXPECT_EQ(volume_sign({kA, kB, (kA + kB) * kS}), 0);
}

// The volume is a b delta: its sign is delta's, though a b delta is some 2^-75 of the terms.
TEST(ExactVolumeSign, ATinyLiftHasItsOwnSign) {
  EXPECT_EQ(volume_sign({kA, kB, (kA + kB) * kS + 0x1p-29}), 1);
  EXPECT_EQ(volume_sign({kA, kB, (kA + kB) * kS - 0x1p-29}), -1);
  int sign = 7;
  ASSERT_TRUE(exact_volume_sign(kP0, kP2, kP1, {kA, kB, (kA + kB) * kS + 0x1p-29}, sign));
  EXPECT_EQ(sign, -1);  // two points swapped
}

TEST(ExactVolumeSign, RefusesAnInexactDifference) {
  int sign = 7;
  EXPECT_FALSE(exact_volume_sign({1, 0, 0}, {0x1p-60, 0, 0}, {0, 1, 0}, {0, 0, 1}, sign));
  EXPECT_EQ(sign, 7);
}

}  // namespace
}  // namespace fdh
