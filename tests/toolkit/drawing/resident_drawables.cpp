#include "toolkit/drawing/resident_drawables.h"

#include "lod_scene.h"

#include <gtest/gtest.h>

using namespace boxlod;

namespace {

// Four packed drawables of equal unpacked size: the test building moved along x.
std::vector<PackedDrawable> four_levels() {
    std::vector<PackedDrawable> packed;
    for (int i = 0; i < 4; ++i) {
        Model model = test::lod_test_building();
        for (Node& node : model.nodes)
            for (Primitive& p : node.primitives)
                for (Eigen::Vector3f& v : p.positions) v.x() += float(10 * i);
        packed.push_back(pack_drawable(model, nullptr));
    }
    return packed;
}

}  // namespace

TEST(ResidentDrawables, ReturnsTheWantedDrawablesInOrder) {
    std::vector<PackedDrawable> packed = four_levels();
    ResidentDrawables resident(0);
    std::vector<const Drawable*> got = resident.acquire({&packed[2], &packed[0]}, 1);
    ASSERT_EQ(got.size(), 2u);
    EXPECT_EQ(got[0]->bounds.min.x(), packed[2].bounds.min.x());
    EXPECT_EQ(got[1]->bounds.min.x(), packed[0].bounds.min.x());
    // Over a zero budget, what a call draws still stays until the next call.
    EXPECT_EQ(resident.counts().resident_bytes, packed[2].unpacked_size + packed[0].unpacked_size);
}

TEST(ResidentDrawables, EvictsTheLeastRecentlyUsedBeyondTheBudget) {
    std::vector<PackedDrawable> packed = four_levels();
    const std::size_t one = packed[0].unpacked_size;
    ASSERT_EQ(packed[3].unpacked_size, one);
    ResidentDrawables resident(2 * one);
    resident.acquire({&packed[0]}, 1);
    resident.acquire({&packed[1]}, 1);
    resident.acquire({&packed[0]}, 1);  // 0 is now more recent than 1
    EXPECT_EQ(resident.counts().unpacked, 2u);
    resident.acquire({&packed[2]}, 1);  // three resident: 1, the least recent, goes
    EXPECT_EQ(resident.counts().evicted, 1u);
    EXPECT_EQ(resident.counts().resident_bytes, 2 * one);
    resident.acquire({&packed[0]}, 1);  // still there
    EXPECT_EQ(resident.counts().unpacked, 3u);
    resident.acquire({&packed[1]}, 1);  // gone: unpacked again
    EXPECT_EQ(resident.counts().unpacked, 4u);
    EXPECT_EQ(resident.counts().peak_bytes, 3 * one);
}

TEST(ResidentDrawables, CountsDoNotDependOnThreads) {
    std::vector<PackedDrawable> packed = four_levels();
    const std::size_t one = packed[0].unpacked_size;
    std::vector<std::vector<const PackedDrawable*>> calls = {{&packed[0], &packed[1], &packed[2]},
                                                             {&packed[3]},
                                                             {&packed[1], &packed[0]},
                                                             {&packed[2], &packed[3]}};
    auto run = [&](int threads) {
        ResidentDrawables resident(2 * one);
        for (const auto& call : calls) resident.acquire(call, threads);
        return std::make_tuple(resident.counts().unpacked, resident.counts().evicted,
                               resident.counts().resident_bytes);
    };
    EXPECT_EQ(run(1), run(2));
    EXPECT_EQ(std::get<0>(run(1)), 8u);  // 0 1 2 | 3, evicting 0 1 | 1 0, evicting 2 3 | 2 3 again
}
