#include "toolkit/selection/face_budget.h"

#include <gtest/gtest.h>

using namespace boxlod;

namespace {

// A unit-radius object at x with levels of the given faces.
SelectionObject object_at(float x, std::vector<std::size_t> faces) {
    SelectionObject object;
    object.center = {x, 0, 0};
    object.radius = 1;
    for (std::size_t f : faces)
        object.levels.push_back(SelectionLevel{f, std::nullopt, std::nullopt, std::nullopt});
    return object;
}

SelectionView camera_at_origin() {
    SelectionView view;
    view.camera.position = {0, 0, 0};
    view.camera.target = {1, 0, 0};
    view.width = 640;
    view.height = 480;
    return view;
}

}  // namespace

TEST(FaceBudget, CoarsensTheLeastImportantFirstUntilTheFacesFit) {
    std::vector<SelectionObject> objects = {object_at(10, {1000, 300, 50, 6}),
                                            object_at(20, {1000, 300, 50, 6}),
                                            object_at(40, {1000, 300, 50, 6})};
    std::vector<double> importance = {3, 2, 1};  // the farthest matters least
    std::vector<int> levels = {0, 0, 0};
    EXPECT_EQ(faces_drawn(objects, levels, 100), 3100u);
    // 2400 fits after the farthest object has dropped one level: 3100 - 700.
    std::size_t faces = fit_face_budget(objects, importance, 2400, levels, 100);
    EXPECT_EQ(faces, 2400u);
    EXPECT_EQ(levels, (std::vector<int>{0, 0, 1}));
    // 1500: the farthest goes all the way (6 faces), then the middle one drops to 300.
    levels = {0, 0, 0};
    faces = fit_face_budget(objects, importance, 1500, levels, 100);
    EXPECT_EQ(levels, (std::vector<int>{0, 1, 3}));
    EXPECT_EQ(faces, 1406u);
    // Within budget already: nothing changes.
    levels = {0, 1, 2};
    EXPECT_EQ(fit_face_budget(objects, importance, 5000, levels, 100), 1450u);
    EXPECT_EQ(levels, (std::vector<int>{0, 1, 2}));
    // Not achievable: every object at its coarsest, and the faces say so.
    levels = {0, 0, 0};
    EXPECT_EQ(fit_face_budget(objects, importance, 50, levels, 100), 118u);
    EXPECT_EQ(levels, (std::vector<int>{3, 3, 3}));
}

TEST(FaceBudget, FacesAreWithinEveryAchievableBudget) {
    std::vector<SelectionObject> objects;
    std::vector<double> importance;
    for (int i = 0; i < 7; ++i) {
        // Faces not monotone in the level for some objects: a box can cost more than a quad it replaces.
        objects.push_back(object_at(float(5 + 7 * i), {std::size_t(900 + 37 * i), std::size_t(200 + 11 * i),
                                                       std::size_t(i % 2 ? 250 : 60), 6}));
        importance.push_back(double((i * 5) % 7));
    }
    std::size_t coarsest = faces_drawn(objects, std::vector<int>(7, 3), 40);
    for (std::size_t budget = coarsest; budget < 9000; budget += 97) {
        std::vector<int> levels = {0, 1, 0, 2, 0, 1, 0};
        std::size_t faces = fit_face_budget(objects, importance, budget, levels, 40);
        EXPECT_LE(faces, budget);
        EXPECT_EQ(faces, faces_drawn(objects, levels, 40));
    }
}

TEST(FaceBudget, ImportanceFallsWithDistanceForEveryStrategy) {
    SelectionView view = camera_at_origin();
    SelectionObject near = object_at(10, {100, 6}), far = object_at(50, {100, 6});
    TextureSizing sizing;
    near.levels[1].sizing = far.levels[1].sizing = sizing;
    for (const Strategy& strategy : std::vector<Strategy>{DistanceBands{{30}}, PixelCount{{1000}},
                                                          ScreenRatio{{0.01}}, BoxDiagonal{}, TexelExact{}})
        EXPECT_GT(selection_importance(strategy, near, view), selection_importance(strategy, far, view))
            << "strategy " << strategy.index();
}
