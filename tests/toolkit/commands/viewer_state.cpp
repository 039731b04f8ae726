#include "toolkit/commands/viewer_state.h"

#include "base/input_error.h"
#include "lod_scene.h"

#include <gtest/gtest.h>

using namespace boxlod;

namespace {

ViewerEvent key(const std::string& name) {
    ViewerEvent e;
    e.key = name;
    return e;
}

struct Fixture {
    Model model = test::lod_test_building();
    ViewerState state;
    Fixture() {
        LodParameters p;
        p.current_level = 0;
        p.resolution = 64;
        p.max_texture_size = 256;
        p.min_texture_size = 64;
        RenderSettings settings;
        settings.camera = camera_at_position({1, 1, 1}, model_bounds(model).center(), 20, 45, 5);
        state = make_viewer_state(model, p, settings, 64, 48, {1, 1, 1});
    }
};

}  // namespace

TEST(ViewerState, KeysCycleModesAndToggleAids) {
    Fixture f;
    ViewerState& s = f.state;
    EXPECT_EQ(s.settings.mode, RenderMode::normal);
    EXPECT_TRUE(apply_event(s, key("m")));
    EXPECT_EQ(s.settings.mode, RenderMode::parallax);
    apply_event(s, key("m"));  // pom,
    apply_event(s, key("m"));  // then albedo: every mode render --mode has
    EXPECT_EQ(s.settings.mode, RenderMode::albedo);
    apply_event(s, key("m"));
    EXPECT_EQ(s.settings.mode, RenderMode::untextured);
    apply_event(s, key("f"));
    apply_event(s, key("x"));
    apply_event(s, key("v"));
    EXPECT_TRUE(s.settings.wireframe && s.axes && s.split_view);
    EXPECT_FALSE(apply_event(s, key("f12")));
    EXPECT_TRUE(s.screenshot);
    EXPECT_FALSE(apply_event(s, key("no-such-key")));
    apply_event(s, key("q"));
    EXPECT_TRUE(s.quit);
}

TEST(ViewerState, OrbitKeepsTheDistanceAndTheWheelChangesIt) {
    Fixture f;
    Camera& c = f.state.settings.camera;
    float distance = (c.position - c.target).norm();
    ViewerEvent drag;
    drag.kind = ViewerEvent::Kind::drag;
    drag.dx = 30;
    drag.dy = -12;
    Eigen::Vector3f before = c.position;
    apply_event(f.state, drag);
    EXPECT_NEAR((c.position - c.target).norm(), distance, distance * 1e-5f);
    EXPECT_GT((c.position - before).norm(), 0.1f);
    ViewerEvent wheel;
    wheel.kind = ViewerEvent::Kind::wheel;
    wheel.dy = 1;
    apply_event(f.state, wheel);
    EXPECT_NEAR((c.position - c.target).norm(), distance * 0.9f, distance * 1e-4f);
    Eigen::Vector3f target = c.target;
    apply_event(f.state, key("d"));  // strafing moves camera and target together
    EXPECT_GT((c.target - target).norm(), 0);
    EXPECT_NEAR((c.position - c.target).norm(), distance * 0.9f, distance * 1e-4f);
}

TEST(ViewerState, LevelKeysRebuildTheLodWithAutoUpdate) {
    Fixture f;
    ViewerState& s = f.state;
    Frame original = render_view(s, 2);
    EXPECT_FALSE(s.lod);
    apply_event(s, key("+"));
    apply_event(s, key("+"));
    EXPECT_TRUE(s.needs_update);
    Frame lod = render_view(s, 2);
    ASSERT_TRUE(s.lod);
    EXPECT_EQ(s.lod->current_level, 2);
    EXPECT_NE(original.color, lod.color);
    // Without auto-update nothing changes until U.
    apply_event(s, key("y"));
    apply_event(s, key("-"));
    render_view(s, 2);
    EXPECT_EQ(s.lod->current_level, 2);
    apply_event(s, key("u"));
    render_view(s, 2);
    EXPECT_EQ(s.lod->current_level, 1);
    // Past the top the level stops at the obtained number of levels.
    apply_event(s, key("y"));
    for (int i = 0; i < 10; ++i) apply_event(s, key("+"));
    render_view(s, 2);
    EXPECT_EQ(s.parameters.current_level, s.chain->obtained_levels());
}

TEST(ViewerState, LightOptionsAndTheManualsGetSetDistance) {
    Fixture f;
    ViewerState& s = f.state;
    float ambient = s.settings.light.ambient;
    apply_event(s, key("2"));
    EXPECT_FLOAT_EQ(s.settings.light.ambient, ambient * 1.25f);
    apply_event(s, key("5"));
    EXPECT_FLOAT_EQ(s.settings.light.specular, RenderSettings{}.light.specular * 0.8f);
    Camera& c = s.settings.camera;
    float distance = (c.position - c.target).norm();
    apply_event(s, key("h"));  // Get Distance
    EXPECT_FLOAT_EQ(s.parameters.distance, distance);
    EXPECT_TRUE(s.needs_update);
    ViewerEvent wheel;
    wheel.kind = ViewerEvent::Kind::wheel;
    wheel.dy = 3;
    apply_event(s, wheel);
    apply_event(s, key("n"));  // Set Distance: back to the sizing distance
    EXPECT_NEAR((c.position - c.target).norm(), distance, distance * 1e-5f);
}

TEST(ViewerState, ReplayLinesParseOrNameTheirPlace) {
    auto e = parse_replay_line("drag 10 -4  # orbit", "events.txt", 3);
    ASSERT_TRUE(e);
    EXPECT_EQ(e->kind, ViewerEvent::Kind::drag);
    EXPECT_EQ(e->dy, -4);
    EXPECT_EQ(parse_replay_line("key M", "events.txt", 1)->key, "m");
    EXPECT_FALSE(parse_replay_line("   # only a comment", "events.txt", 2));
    try {
        parse_replay_line("jump 3", "events.txt", 7);
        FAIL();
    } catch (const InputError& error) {
        EXPECT_EQ(std::string(error.what()), "events.txt: line 7: unknown event 'jump' (key, drag, wheel)");
    }
    EXPECT_THROW(parse_replay_line("wheel", "events.txt", 1), InputError);
    EXPECT_THROW(parse_replay_line("key m extra", "events.txt", 1), InputError);
    // Numbers within their ranges (SDL reads ints; a wheel of 1e30 steps put the camera at infinity).
    try {
        parse_replay_line("wheel -1000", "events.txt", 4);
        FAIL();
    } catch (const InputError& error) {
        EXPECT_EQ(std::string(error.what()),
                  "events.txt: line 4: N: expected a number in [-100, 100], got '-1000'");
    }
    EXPECT_THROW(parse_replay_line("drag 1e30 0", "events.txt", 1), InputError);
    EXPECT_THROW(parse_replay_line("drag nan 0", "events.txt", 1), InputError);
    EXPECT_THROW(parse_replay_line("wheel 0x10", "events.txt", 1), InputError);
}

// However far a replay wheels, the camera stays where a parameter file can save it.
TEST(ViewerState, WheelingStaysWithinSavablePositions) {
    Fixture f;
    ViewerState& s = f.state;
    ViewerEvent wheel;
    wheel.kind = ViewerEvent::Kind::wheel;
    for (float steps : {-100.0f, 100.0f}) {
        wheel.dy = steps;
        for (int i = 0; i < 50; ++i) apply_event(s, wheel);
        const Camera& c = s.settings.camera;
        EXPECT_TRUE(c.position.allFinite());
        EXPECT_TRUE(parameter_range::position.contains(c.position.cwiseAbs().maxCoeff()));
        EXPECT_GT((c.position - c.target).norm(), 0);
    }
}
