// `boxlod view`: the interactive viewer (SDL2) over the software renderer.
#include "base/atomic_write.h"
#include "base/distinct_files.h"
#include "base/input_file.h"
#include "renderer/overlays.h"
#include "renderer/text_overlay.h"
#include "toolkit/commands/commands.h"
#include "toolkit/commands/lod_options.h"
#include "toolkit/commands/render_options.h"
#include "toolkit/commands/sdl_library.h"
#include "toolkit/commands/viewer_state.h"
#include "toolkit/formats/model_io.h"
#include "toolkit/lod/lod_export.h"
#include "toolkit/lod/pages/level_pages.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace boxlod {
namespace {

// SDL events in, viewer events out; SDL's key names, lower case ("m", "f12", "keypad +").
std::optional<ViewerEvent> translate(const SDL_Event& event) {
    ViewerEvent e;
    if (event.type == SDL_KEYDOWN) {
        e.key = sdl().SDL_GetKeyName(event.key.keysym.sym);
        for (char& c : e.key) c = char(std::tolower(static_cast<unsigned char>(c)));
        return e;
    }
    if (event.type == SDL_MOUSEMOTION && (event.motion.state & SDL_BUTTON_LMASK)) {
        e.kind = ViewerEvent::Kind::drag;
        e.dx = float(event.motion.xrel);
        e.dy = float(event.motion.yrel);
        return e;
    }
    if (event.type == SDL_MOUSEWHEEL) {
        e.kind = ViewerEvent::Kind::wheel;
        e.dy = float(event.wheel.y);
        return e;
    }
    return std::nullopt;
}

// A replayed event goes through SDL's queue like a real one.
SDL_Event to_sdl(const ViewerEvent& e) {
    SDL_Event event{};
    if (e.kind == ViewerEvent::Kind::key) {
        event.type = SDL_KEYDOWN;
        event.key.keysym.sym = sdl().SDL_GetKeyFromName(e.key.c_str());
    } else if (e.kind == ViewerEvent::Kind::drag) {
        event.type = SDL_MOUSEMOTION;
        event.motion.state = SDL_BUTTON_LMASK;
        event.motion.xrel = int(e.dx);
        event.motion.yrel = int(e.dy);
    } else {
        event.type = SDL_MOUSEWHEEL;
        event.wheel.y = int(e.dy);
    }
    return event;
}

std::vector<ViewerEvent> read_replay(const std::string& path) {
    std::istringstream in(read_input_file(path, "event file"));
    std::vector<ViewerEvent> events;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number)
        if (auto e = parse_replay_line(line, path, number)) {
            if (e->kind == ViewerEvent::Kind::key && sdl().SDL_GetKeyFromName(e->key.c_str()) == SDLK_UNKNOWN)
                throw_input_error(path, "line " + std::to_string(number), "unknown key '" + e->key + "'");
            events.push_back(*e);
            if (events.size() > max_replay_events)
                throw_input_error(path, "line " + std::to_string(number),
                                  "more than " + std::to_string(max_replay_events) +
                                      " events (SDL's queue holds them all at once)");
        }
    return events;
}

// The picture on screen: the frame, the axes, the divider, the LoD texture and the text.
Image8 compose(ViewerState& s, const Frame& frame) {
    Frame shown = frame;
    if (s.axes) {
        Bounds b = model_bounds(*s.model);
        draw_axes(shown, s.settings.camera, b.min, b.size().maxCoeff() * 0.5f);
    }
    if (s.split_view) draw_divider(shown, s.width / 2, {0, 0, 0});
    Image8 image = frame_to_srgb8(shown);
    if (s.show_texture && s.lod && !s.lod->atlas.pages.empty()) {  // the colour + normal pair of one page
        int page = std::min(s.texture_page, int(s.lod->atlas.pages.size()) - 1);
        const Texture& color = s.lod->model.textures[std::size_t(lod_page(page).color)];
        const Texture& normal = s.lod->model.textures[std::size_t(lod_page(page).normal)];
        int size = std::max(1, int(float(std::min(s.width / 2, s.height)) * 0.5f * s.texture_scale));
        for (int y = 0; y < std::min(size, s.height); ++y)
            for (int x = 0; x < std::min(2 * size, s.width); ++x) {
                const Texture& t = x < size ? color : normal;
                int tx = (x % size) * t.image.width / size, ty = y * t.image.height / size;
                std::copy_n(t.image.at(tx, ty), 3, image.at(x, s.height - std::min(size, s.height) + y));
            }
    }
    const std::uint8_t ink[3] = {20, 20, 20};
    int y = 6;
    for (const std::string& line : overlay_lines(s)) y += draw_text(image, 6, y, line, ink, 1) + 2;
    return image;
}

// The SDL window showing the software-rendered frame; closed when it goes. No display to open it on is
// the caller's to mend, as bad input is (exit 2); so is a person's viewer on SDL's off-screen drivers,
// which SDL falls back to without a display and where no event would ever come.
struct Window {
    SDL_Window* window = nullptr;
    SDL_Renderer* renderer = nullptr;
    SDL_Texture* texture = nullptr;

    Window(const std::string& title, int width, int height, bool interactive) {
        const std::string remedy = ": set DISPLAY (or WAYLAND_DISPLAY), or give --screenshot or --replay";
        if (sdl().SDL_Init(SDL_INIT_VIDEO) != 0)
            throw InputError(std::string("cannot open a window (") + sdl().SDL_GetError() + ")" + remedy);
        const char* driver = sdl().SDL_GetCurrentVideoDriver();
        if (interactive && driver && (std::string(driver) == "offscreen" || std::string(driver) == "dummy")) {
            close();
            throw InputError(std::string("no display to open a window on (SDL's video driver is ") + driver +
                             ")" + remedy);
        }
        window = sdl().SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED,
                                        width, height, 0);
        renderer = window ? sdl().SDL_CreateRenderer(window, -1, SDL_RENDERER_SOFTWARE) : nullptr;
        texture = renderer ? sdl().SDL_CreateTexture(renderer, SDL_PIXELFORMAT_RGB24,
                                                     SDL_TEXTUREACCESS_STREAMING, width, height)
                           : nullptr;
        if (!texture) {
            std::string error = sdl().SDL_GetError();
            close();
            throw InputError("cannot open a window (" + error + ")" + remedy);
        }
    }
    ~Window() { close(); }
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    void show(const Image8& image) {
        sdl().SDL_UpdateTexture(texture, nullptr, image.pixels.data(), image.width * 3);
        sdl().SDL_RenderCopy(renderer, texture, nullptr, nullptr);
        sdl().SDL_RenderPresent(renderer);
    }

    void close() {
        if (texture) sdl().SDL_DestroyTexture(texture);
        if (renderer) sdl().SDL_DestroyRenderer(renderer);
        if (window) sdl().SDL_DestroyWindow(window);
        texture = nullptr;
        renderer = nullptr;
        window = nullptr;
        sdl().SDL_Quit();
    }
};

// The state the viewer starts in: the model and LoD parameters from MODEL or
// PARAMS.txt, the view from the render options (a parameter file's camera and
// light win), at level 0 unless a level is asked for.
ViewerState start_state(const Arguments& a, const Model& model, LodParameters parameters) {
    View view = view_from_arguments(a, model_bounds(model));
    if (parameters.camera) view.settings.camera = *parameters.camera;
    if (parameters.light) view.settings.light = *parameters.light;
    if (a.has("mode"))
        parameters.render_mode = view.settings.mode;
    else
        view.settings.mode = parameters.render_mode;
    ViewerState state =
        make_viewer_state(model, parameters, view.settings, view.width, view.height, view.background);
    state.light_follows_camera = !(parameters.light || a.has("light"));
    std::vector<std::string> positions = camera_position_names();
    for (std::size_t i = 0; i < positions.size(); ++i)  // C continues from the start position
        if (camera_direction(positions[i]) == camera_direction(a.text("camera")))
            state.camera_position = int(i);
    return state;
}

// Parameters read back take over the session (the model stays), with the
// camera and light they state; without a light, the light follows the camera.
void load_session_parameters(ViewerState& state, const std::string& path) {
    LodParameters p = load_parameters(path);
    p.model = state.parameters.model;
    state.parameters = p;
    if (p.camera) state.settings.camera = *p.camera;
    if (p.light) state.settings.light = *p.light;
    state.light_follows_camera = !p.light;
    state.settings.mode = p.render_mode;
    state.chain.reset();
    state.needs_update = true;
    state.message = "loaded " + path;
}

// What the keys asked of the front end: a screenshot, parameters saved or
// loaded, the LoD exported. A file that cannot be written or read is shown in
// the window and on stderr, and counted in `failures`, not the end of the
// session. Returns true when the frame must be redrawn.
bool serve_requests(ViewerState& state, const Frame& frame, const Arguments& a, int threads, int& screenshots,
                    int& failures) {
    auto shown = [&](auto action) {
        try {
            action();
        } catch (const InputError& error) {
            state.message = error.what();
            std::fprintf(stderr, "boxlod view: %s\n", error.what());
            ++failures;
        }
    };
    const std::string params_out = a.text("params-out");
    bool redraw = false;
    if (state.screenshot) {  // the rendered frame, without the text overlay
        std::string path = a.text("screenshot", "boxlod-view-" + std::to_string(screenshots++) + ".png");
        shown([&] {
            write_png(path, frame_to_srgb8(frame));
            std::printf("screenshot = %s\n", path.c_str());
        });
        state.screenshot = false;
    }
    if (state.save_parameters) {
        LodParameters p = state.parameters;
        p.camera = state.settings.camera;
        p.light = state.settings.light;
        shown([&] {
            save_parameters(params_out, p);
            state.message = "saved " + params_out;
        });
        state.save_parameters = false;
        redraw = true;
    }
    if (state.load_parameters) {
        shown([&] { load_session_parameters(state, params_out); });
        state.load_parameters = false;
        redraw = true;
    }
    if (state.export_lod) {
        if (state.lod && state.chain) {
            std::string name = std::filesystem::path(state.parameters.model).stem().string() + "_L" +
                               std::to_string(state.parameters.current_level);
            std::string folder = a.text("export-dir");
            shown([&] {
                export_lod(*state.lod, state.chain->parameters(), folder, name, frame_to_srgb8(frame),
                           threads);
                state.message = "exported " + folder + "/" + name + ".gltf";
            });
        } else {
            state.message = "nothing to export at level 0";
        }
        state.export_lod = false;
        redraw = true;
    }
    return redraw;
}

// --replay's events (none without it), the outputs they write checked before the window opens, so that a
// bad one is refused with nothing written.
std::vector<ViewerEvent> checked_replay(const Arguments& a) {
    std::vector<ViewerEvent> replay =
        a.has("replay") ? read_replay(a.text("replay")) : std::vector<ViewerEvent>{};
    auto pressed = [&](const std::string& name) {
        return std::any_of(replay.begin(), replay.end(), [&](const ViewerEvent& e) { return e.key == name; });
    };
    if (pressed("f5")) check_output_file(a.text("params-out"));
    if (pressed("f6")) check_output_directory(a.text("export-dir"));
    if (pressed("f12") && !a.has("screenshot")) check_output_file("boxlod-view-0.png");
    return replay;
}

int run_view(const Arguments& a) {
    if (a.has("screenshot")) check_output_file(a.text("screenshot"), {".png"});
    LodParameters parameters = lod_parameters_from(a);
    check_distinct_files(
        {{"MODEL", model_file_of(parameters.model)}, {"--replay", a.text("replay", "")}},
        {{"--params-out", a.text("params-out")}, {"--screenshot", a.text("screenshot", "")}});
    bool from_parameter_file = std::filesystem::path(a.positionals[0]).extension() == ".txt";
    if (!a.has("level") && !from_parameter_file) parameters.current_level = 0;  // start with the original
    Model model = load_parameters_model(parameters);
    ViewerState state = start_state(a, model, parameters);
    if (parameters.current_level > 0 && !model.is_lod) {  // a level asked for exists, or no window opens (73)
        state.chain = std::make_unique<Chain>(model, state.parameters, state.settings.threads);
        if (parameters.current_level > state.chain->obtained_levels())
            throw_input_error(parameters.model, "",
                              "--level " + std::to_string(parameters.current_level) +
                                  " is past the levels obtained, 0.." +
                                  std::to_string(state.chain->obtained_levels()));
    }
    const std::vector<ViewerEvent> replay = checked_replay(a);
    const bool replaying = a.has("replay") || a.has("screenshot");  // an empty replay stops at once
    Window window("boxlod view " + a.positionals[0], state.width, state.height, !replaying);
    for (const ViewerEvent& e : replay) {
        SDL_Event event = to_sdl(e);
        if (sdl().SDL_PushEvent(&event) != 1)
            throw InputError(a.text("replay") + ": SDL's event queue is full");
    }
    int threads = state.settings.threads, screenshots = 0, failures = 0;
    bool redraw = true;
    Frame frame;
    while (!state.quit) {
        SDL_Event event;
        // Replays drain the queue without waiting; people get a responsive wait.
        bool got = replaying ? sdl().SDL_PollEvent(&event) : sdl().SDL_WaitEventTimeout(&event, 100);
        if (got) {
            if (event.type == SDL_QUIT) break;
            if (auto e = translate(event)) redraw = apply_event(state, *e) || redraw;
        } else if (replaying) {
            state.screenshot = a.has("screenshot") && failures == 0;  // a failed replay leaves no screenshot
            state.quit = true;
        }
        if (redraw || state.screenshot) {
            frame = render_view(state, threads);
            window.show(compose(state, frame));
            redraw = false;
        }
        redraw = serve_requests(state, frame, a, threads, screenshots, failures) || redraw;
    }
    return replaying && failures > 0
               ? 2
               : 0;  // a script whose action failed is bad input; a person saw the message
}

}  // namespace

Subcommand view_subcommand() {
    std::vector<Option> options = {
        {"replay", "EVENTS", "replay an event file (lines 'key m', 'drag DX DY', 'wheel N'), then stop"},
        {"screenshot", "FILE", "write the final frame (without the text overlay) as PNG"},
        {"params-out", "FILE", "where F5 saves and F9 loads parameters", std::nullopt,
         "boxlod-view.params.txt"},
        {"export-dir", "DIR", "where F6 exports the current LoD", std::nullopt, "boxlod-view-export"},
    };
    // The camera's distance and fovy are the render options' (and size the LoD's textures too).
    options = with_options(with_options(options, render_options()), lod_options());
    return {{"view", "MODEL|PARAMS.txt",
             "Interactive viewer: fly around a model and its LoD, switch modes and levels, compare.\n" +
                 viewer_key_help(),
             options, 1, 1},
            run_view};
}

}  // namespace boxlod
