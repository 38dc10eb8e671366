// Plane polygons of the mortar integration: clipping convex polygons, splitting a non-convex
// quad into convex pieces.
#include "core/contact/MortarClipping.hpp"

#include <gtest/gtest.h>
#include <stdexcept>
#include <vector>

namespace contactlab {
namespace {

TEST(MortarClipping, ClipsConvexPolygons) {
  const Polygon2 square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const Polygon2 shifted{{0.5, 0.5}, {1.5, 0.5}, {1.5, 1.5}, {0.5, 1.5}};
  EXPECT_NEAR(signedArea(clipConvex(square, shifted, 1e-12)), 0.25, 1e-16);
  // A coincident clip polygon keeps the subject, without near-duplicate vertices.
  EXPECT_EQ(clipConvex(square, square, 1e-12).size(), 4u);
  EXPECT_TRUE(clipConvex(square, {{2, 0}, {3, 0}, {3, 1}}, 1e-12).empty());
  // A diamond inside the square's corners: an octagon.
  const Polygon2 diamond{{0.5, -0.2}, {1.2, 0.5}, {0.5, 1.2}, {-0.2, 0.5}};
  const Polygon2 octagon = clipConvex(square, diamond, 1e-12);
  EXPECT_EQ(octagon.size(), 8u);
  EXPECT_NEAR(signedArea(octagon), 1 - 4 * 0.5 * 0.3 * 0.3, 1e-15);
}

TEST(MortarClipping, SplitsANonConvexQuadAtItsReflexVertex) {
  // Clockwise dart with its reflex vertex at (0.5, 0.4).
  const Polygon2 dart{{0, 0}, {0.5, 1}, {1, 0}, {0.5, 0.4}};
  const std::vector<Polygon2> pieces = convexPieces(dart);
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_NEAR(signedArea(pieces[0]) + signedArea(pieces[1]), -signedArea(dart), 1e-15);
  for (const Polygon2& piece : pieces)
    EXPECT_GT(signedArea(piece), 0.0);
  EXPECT_EQ(convexPieces({{0, 0}, {1, 0}, {1, 1}, {0, 1}}).size(), 1u);
  EXPECT_THROW(convexPieces({{0, 0}, {1, 1}, {1, 0}, {0, 1}}), std::invalid_argument);  // bow tie
}

}  // namespace
}  // namespace contactlab
