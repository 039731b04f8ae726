#include "toolkit/cgal/box_fit.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

namespace boxlod {
namespace {

bool is_rotation(const Eigen::Matrix3d& m) {
    return (m.transpose() * m).isApprox(Eigen::Matrix3d::Identity(), 1e-12) &&
           std::abs(m.determinant() - 1) < 1e-12;
}

TEST(BoxFit, OrthonormalFrameKeepsARotation) {
    Eigen::Matrix3d r = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    EXPECT_TRUE(orthonormal_frame(r).isApprox(r, 1e-14));
    EXPECT_EQ(orthonormal_frame(Eigen::Matrix3d::Identity()), Eigen::Matrix3d::Identity());
}

TEST(BoxFit, OrthonormalFrameRepairsBadAxes) {
    Eigen::Matrix3d left_handed = Eigen::Vector3d(1, 1, -1).asDiagonal();
    Eigen::Matrix3d frame = orthonormal_frame(left_handed);
    EXPECT_TRUE(is_rotation(frame));
    EXPECT_EQ(frame.col(2), Eigen::Vector3d(0, 0, 1));
    Eigen::Matrix3d skewed;
    skewed << 2, 1, 0, 0, 1, 0, 0, 0, 5;  // columns (2,0,0), (1,1,0), (0,0,5)
    frame = orthonormal_frame(skewed);
    EXPECT_TRUE(is_rotation(frame));
    EXPECT_TRUE(frame.col(1).isApprox(Eigen::Vector3d(0, 1, 0), 1e-15));
    EXPECT_TRUE(is_rotation(orthonormal_frame(Eigen::Matrix3d::Zero())));
    Eigen::Matrix3d parallel = Eigen::Matrix3d::Zero();
    parallel.col(0) = parallel.col(1) = Eigen::Vector3d(0, 3, 4);
    frame = orthonormal_frame(parallel);
    EXPECT_TRUE(is_rotation(frame));
    EXPECT_TRUE(frame.col(0).isApprox(Eigen::Vector3d(0, 0.6, 0.8), 1e-15));
}

TEST(BoxFit, FitBoxIsTheTightBoxForItsAxes) {
    std::vector<Eigen::Vector3f> points{{0, 0, 0}, {2, 4, 6}, {1, 1, 1}};
    OrientedBox box = fit_box(Eigen::Matrix3d::Identity(), points);
    EXPECT_EQ(box.center, Eigen::Vector3f(1, 2, 3));
    EXPECT_EQ(box.half_extents, Eigen::Vector3f(1, 2, 3));
    EXPECT_EQ(box.axes, Eigen::Matrix3f::Identity());
}

TEST(BoxFit, FitBoxEnclosesAfterRounding) {
    Eigen::Matrix3d r = Eigen::AngleAxisd(0.4, Eigen::Vector3d(3, -1, 2).normalized()).toRotationMatrix();
    std::vector<Eigen::Vector3f> points;
    for (int i = 0; i < 50; ++i) points.emplace_back(0.37f * i, 1000.1f - 0.11f * i * i, 3.3f * (i % 7));
    OrientedBox box = fit_box(r, points);
    const Eigen::Matrix3d axes = box.axes.cast<double>();
    for (const Eigen::Vector3f& p : points) {
        Eigen::Vector3d local = axes.transpose() * (p.cast<double>() - box.center.cast<double>());
        EXPECT_TRUE((local.cwiseAbs().array() <= box.half_extents.cast<double>().array()).all())
            << (local.cwiseAbs() - box.half_extents.cast<double>()).transpose();
    }
}

TEST(BoxFit, MinThicknessAndCorners) {
    OrientedBox box;
    box.center = {1, 0, 0};
    box.half_extents = {2, 0, 0.5f};
    box = with_min_thickness(box, 0.25f);
    EXPECT_EQ(box.half_extents, Eigen::Vector3f(2, 0.125f, 0.5f));
    auto corners = box_corners(box);
    EXPECT_EQ(corners[0], Eigen::Vector3f(-1, -0.125f, -0.5f));
    EXPECT_EQ(corners[7], Eigen::Vector3f(3, 0.125f, 0.5f));
}

}  // namespace
}  // namespace boxlod
