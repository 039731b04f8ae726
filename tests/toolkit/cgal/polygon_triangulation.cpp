#include "toolkit/cgal/polygon_triangulation.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <cmath>

namespace boxlod {
namespace {

using Ring = std::vector<Eigen::Vector3d>;

std::vector<Eigen::Vector3d> all_points(const std::vector<Ring>& rings, const PolygonTriangles& triangles) {
    std::vector<Eigen::Vector3d> points;
    for (const Ring& ring : rings) points.insert(points.end(), ring.begin(), ring.end());
    points.insert(points.end(), triangles.added_points.begin(), triangles.added_points.end());
    return points;
}

// The triangles' area, and whether each turns about `normal`.
double area_about(const std::vector<Ring>& rings, const PolygonTriangles& triangles,
                  const Eigen::Vector3d& normal, bool& all_turn) {
    const auto points = all_points(rings, triangles);
    double area = 0;
    all_turn = true;
    for (const auto& t : triangles.triangles) {
        const Eigen::Vector3d cross = (points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]);
        area += cross.norm() / 2;
        all_turn = all_turn && cross.dot(normal) > 0;
    }
    return area;
}

// A wall 4 x 3 standing in the x-z plane, facing -y, with a 1 x 1 window hole.
const Ring wall{{0, 0, 0}, {4, 0, 0}, {4, 0, 3}, {0, 0, 3}};
const Ring window{{1, 0, 1}, {1, 0, 2}, {2, 0, 2}, {2, 0, 1}};

TEST(PolygonTriangulation, AHoleIsLeftOpenAndTrianglesTurnAsTheOuterRing) {
    const PolygonTriangles triangles = triangulate_polygon({wall, window});
    bool all_turn = false;
    EXPECT_NEAR(area_about({wall, window}, triangles, {0, -1, 0}, all_turn), 12 - 1, 1e-12);
    EXPECT_TRUE(all_turn);
    EXPECT_TRUE(triangles.added_points.empty());
    EXPECT_EQ(triangles.triangles.size(), 8u);  // 8 points, 2 rings: n + 2h - 2 triangles
}

TEST(PolygonTriangulation, AConcaveRingFarFromTheOriginIsExact) {
    // An L-shaped roof 100 km out, facing up: 3 of its 4 unit squares.
    const Eigen::Vector3d far(1e5, 4e5, 20);
    Ring roof;
    for (Eigen::Vector3d p :
         {Eigen::Vector3d(0, 0, 0), {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}})
        roof.push_back(far + p);
    const PolygonTriangles triangles = triangulate_polygon({roof});
    bool all_turn = false;
    EXPECT_NEAR(area_about({roof}, triangles, {0, 0, 1}, all_turn), 3, 1e-9);
    EXPECT_TRUE(all_turn);
}

TEST(PolygonTriangulation, CrossingRingsMeetAtAddedPoints) {
    // A hole that sticks out of its polygon crosses its border twice.
    const Ring outer{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
    const Ring hole{{1, 1, 0}, {3, 1, 0}, {3, 3, 0}, {1, 3, 0}};
    const PolygonTriangles triangles = triangulate_polygon({outer, hole});
    ASSERT_EQ(triangles.added_points.size(), 2u);
    for (const Eigen::Vector3d& p : triangles.added_points)
        EXPECT_TRUE((p - Eigen::Vector3d(2, 1, 0)).norm() < 1e-12 ||
                    (p - Eigen::Vector3d(1, 2, 0)).norm() < 1e-12);
    bool all_turn = false;
    area_about({outer, hole}, triangles, {0, 0, 1}, all_turn);
    EXPECT_TRUE(all_turn);
}

// A ring wound as a star {n/k} crosses itself about n^2/2 times: refused, not triangulated.
TEST(PolygonTriangulation, ARingThatCrossesItselfMoreThanItHasPointsIsRefused) {
    auto star = [](int n, int k) {
        Ring ring;
        for (int j = 0; j < n; ++j) {
            const double angle = 2 * M_PI * double(j * k % n) / n;
            ring.emplace_back(std::cos(angle), std::sin(angle), 0);
        }
        return ring;
    };
    const PolygonTriangles crossed = triangulate_polygon({star(201, 100)});
    EXPECT_TRUE(crossed.too_many_crossings);
    EXPECT_TRUE(crossed.triangles.empty());
    const PolygonTriangles pentagram = triangulate_polygon({star(5, 2)});  // 5 crossings
    EXPECT_FALSE(pentagram.too_many_crossings);
    EXPECT_EQ(pentagram.added_points.size(), 5u);
}

TEST(PolygonTriangulation, APolygonWithoutAreaGivesNoTriangle) {
    EXPECT_TRUE(triangulate_polygon({{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}}).triangles.empty());
    EXPECT_TRUE(triangulate_polygon({{{0, 0, 0}, {1, 0, 0}}}).triangles.empty());
    EXPECT_TRUE(triangulate_polygon({}).triangles.empty());
}

}  // namespace
}  // namespace boxlod
