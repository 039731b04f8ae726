// What `boxlod view` shows and how input changes it, without any window: the
// camera, the render options, the LoD being looked at. The SDL front end
// (toolkit/commands/command_view.cpp) turns key and mouse events into ViewerEvents;
// a replay file does the same, so a scripted session renders exactly what a
// person would see.
#pragma once
#include "base/input_error.h"
#include "toolkit/drawing/drawable.h"
#include "toolkit/lod/chain/chain.h"

#include <cstddef>
#include <memory>
#include <string>

namespace boxlod {

struct ViewerEvent {
    enum class Kind { key, drag, wheel } kind = Kind::key;
    std::string key;       // SDL key name, lower case: "m", "w", "+", "f12", ...
    float dx = 0, dy = 0;  // drag: pixels moved with the left button held; wheel: dy steps
};

struct ViewerState {
    const Model* model = nullptr;  // the loaded model (an exported LoD is only shown, never rebuilt)
    LodParameters parameters;      // level mode, box kind, current level, sizing, render mode, ...
    RenderSettings settings;       // camera, light, mode, wireframe: what render() gets
    int width = 1024, height = 768;
    Eigen::Vector3f background{1, 1, 1};
    bool axes = false, split_view = false, show_statistics = true, show_texture = false;
    int texture_page = 0;
    float texture_scale = 1;
    bool light_follows_camera =
        true;                  // the default light, as `boxlod render` places it; off once a light is set
    bool auto_update = true;   // the manual's Auto-Update: rebuild whenever a parameter changes
    bool needs_update = true;  // parameters changed since the LoD was built
    bool update_now = false;   // the manual's Update: rebuild even without auto-update
    int camera_position = 0;   // index into camera_position_names(), for the cycling key
    std::string message;       // the last action, for the overlay
    // Requests for the front end.
    bool screenshot = false, save_parameters = false, load_parameters = false, export_lod = false,
         quit = false;

    // The LoD currently shown (null at level 0 or for an LoD file) and what is drawn.
    std::unique_ptr<Chain> chain;  // level c as build --all-levels makes it (chain.h)
    std::unique_ptr<Lod> lod;
    std::unique_ptr<DrawableModel> original_drawable, lod_drawable;
};

// A state showing `model` with `settings` (the same defaults as `boxlod render`).
ViewerState make_viewer_state(const Model& model, const LodParameters& parameters,
                              const RenderSettings& settings, int width, int height,
                              const Eigen::Vector3f& background);

// Keys as viewer_key_help() lists them. Returns true when the picture changes.
bool apply_event(ViewerState& state, const ViewerEvent& event);
std::string viewer_key_help();

// Rebuilds the LoD if needed (and allowed), then renders the frame without overlays.
Frame render_view(ViewerState& state, int threads);

// Lines for the on-screen overlay: settings and statistics.
std::vector<std::string> overlay_lines(const ViewerState& state);

// One line of a replay file: "key m", "drag 10 -4", "wheel 2". Blank lines and
// # comments give std::nullopt; anything else is an InputError naming file:line.
std::optional<ViewerEvent> parse_replay_line(const std::string& line, const std::string& file, int number);
constexpr NumberRange replay_drag_range{-16384, 16384};  // pixels
constexpr NumberRange replay_wheel_range{-100, 100};     // steps
// SDL's event queue holds 65,535 events; a replay is queued whole.
constexpr std::size_t max_replay_events = 60000;

}  // namespace boxlod
