// The preview window: SDL2 for the window and input, an OpenGL 2 context
// for Dear ImGui to draw in, the rendered image as one texture.
#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <SDL.h>
#include <SDL_opengl.h>
#include <backends/imgui_impl_opengl2.h>
#include <backends/imgui_impl_sdl.h>
#include <imgui.h>

#include "core/error.hpp"
#include "output/atomic_file.hpp"
#include "preview/file_watch.hpp"
#include "preview/preview.hpp"
#include "preview/preview_panel.hpp"
#include "preview/preview_worker.hpp"

namespace facet {
namespace {

// While the camera or a slider moves, each view is rendered once, at the
// size that takes about this long.
constexpr double kInteractiveBudgetMs = 60;

}  // namespace

int current_frame(const PreviewState& state) {
    if (!state.frames.empty())
        return state.frames[std::min(state.frame_index, state.frames.size() - 1)];
    return state.scene ? state.scene->output.frames.front() : kSceneFirstFrame;
}

PreviewRequest preview_request(const PreviewState& state) {
    PreviewRequest request;
    request.overrides = tweak_overrides(state.tweaks);
    if (state.view && state.scene && state.camera_index < state.scene->cameras.size())
        request.camera = camera_override(*state.view, state.scene->cameras[state.camera_index]);
    request.frame = current_frame(state);
    request.camera_index = state.camera_index;
    request.pass = state.pass;
    // Dragging: a new view every few tens of milliseconds; playing: one
    // every frame time.
    request.live = state.playing || state.interacting;
    request.live_budget_ms =
        state.playing && state.scene ? 1000.0 / state.scene->output.fps : kInteractiveBudgetMs;
    request.files_version = state.files_version;
    return request;
}

// The preview needs a display; say so plainly instead of SDL's message.
void require_display() {
    const auto set = [](const char* name) {
        const char* value = std::getenv(name);
        return value && *value;
    };
    if (!set("DISPLAY") && !set("WAYLAND_DISPLAY") && !set("SDL_VIDEODRIVER"))
        throw Error(ExitCode::invalid_input,
                    "facet preview needs a display, and neither DISPLAY nor WAYLAND_DISPLAY is "
                    "set (on a machine without one use facet render, or run the preview under "
                    "xvfb-run)");
}

namespace {

using Clock = std::chrono::steady_clock;

constexpr float kPanelWidth = 380;
constexpr float kStatusHeight = 26;
constexpr double kFilePollSeconds = 0.15;
constexpr float kOrbitDegreesPerPixel = 0.4f;
constexpr float kDollyPerWheelStep = 0.9f;
constexpr double kWheelSettleSeconds = 0.3;  // a wheel turn counts as a drag this long

double seconds_between(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}

// SDL, its OpenGL context, ImGui and the image's texture, made and
// released in order.
class Window {
  public:
    explicit Window(const std::string& title) {
        require_display();
        // Only a real windowing system: asked for none, SDL would fall back
        // to its off-screen driver where the named display cannot be
        // reached, and render forever with no window (SDL_VIDEODRIVER, when
        // the user sets it, still wins).
        if (!std::getenv("SDL_VIDEODRIVER"))
            SDL_SetHint(SDL_HINT_VIDEODRIVER,
                        std::getenv("WAYLAND_DISPLAY") ? "wayland,x11" : "x11,wayland");
        if (SDL_Init(SDL_INIT_VIDEO) != 0)
            throw Error(ExitCode::invalid_input,
                        std::string("facet preview cannot open a window: ") + SDL_GetError());
        SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
        window_ = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                                   960, 600, SDL_WINDOW_OPENGL | SDL_WINDOW_RESIZABLE);
        if (!window_) fail("cannot open a window");
        context_ = SDL_GL_CreateContext(window_);
        if (!context_) fail("cannot make an OpenGL context");
        SDL_GL_MakeCurrent(window_, context_);
        SDL_GL_SetSwapInterval(0);  // the loop paces itself
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the user's folder
        ImGui::StyleColorsDark();
        ImGui_ImplSDL2_InitForOpenGL(window_, context_);
        ImGui_ImplOpenGL2_Init();
        glGenTextures(1, &texture_);
    }
    ~Window() {
        glDeleteTextures(1, &texture_);
        ImGui_ImplOpenGL2_Shutdown();
        ImGui_ImplSDL2_Shutdown();
        ImGui::DestroyContext();
        SDL_GL_DeleteContext(context_);
        SDL_DestroyWindow(window_);
        SDL_Quit();
    }
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    SDL_Window* sdl() const { return window_; }
    bool has_image() const { return image_width_ > 0; }
    int image_width() const { return image_width_; }

    void upload(const PreviewImage& image) {
        glBindTexture(GL_TEXTURE_2D, texture_);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, image.width, image.height, 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, image.rgba.data());
        image_width_ = image.width;
        image_height_ = image.height;
    }

    // Draws the image into x, y, width, height: pixel for pixel when the
    // sizes agree (so the window shows exactly the file's pixels), else
    // smoothly scaled (a quarter-size step, or a window too small).
    void draw_image(float width, float height) const {
        if (!has_image()) return;
        const bool exact =
            std::lround(width) == image_width_ && std::lround(height) == image_height_;
        glBindTexture(GL_TEXTURE_2D, texture_);
        const GLint filter = exact ? GL_NEAREST : GL_LINEAR;
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
        ImGui::GetBackgroundDrawList()->AddImage(
            reinterpret_cast<ImTextureID>(static_cast<intptr_t>(texture_)), ImVec2(0, 0),
            ImVec2(width, height));
    }

    void present() {
        ImGui::Render();
        const ImGuiIO& io = ImGui::GetIO();
        glViewport(0, 0, static_cast<int>(io.DisplaySize.x), static_cast<int>(io.DisplaySize.y));
        glClearColor(0.15f, 0.15f, 0.16f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
        SDL_GL_SwapWindow(window_);
        glFinish();  // on screen before the loop says it is
    }

  private:
    [[noreturn]] void fail(const std::string& what) {
        const std::string message = "facet preview " + what + ": " + SDL_GetError();
        if (window_) SDL_DestroyWindow(window_);
        SDL_Quit();
        throw Error(ExitCode::invalid_input, message);
    }

    SDL_Window* window_ = nullptr;
    SDL_GLContext context_ = nullptr;
    GLuint texture_ = 0;
    int image_width_ = 0, image_height_ = 0;
};

// The loop's state besides PreviewState: input, timing, the worker.
class PreviewSession {
  public:
    explicit PreviewSession(const PreviewOptions& options)
        : options_(options),
          window_("facet preview - " + std::filesystem::path(options.scene).filename().string()),
          worker_(options.scene, options.scene_options, options.threads),
          watch_({options.out_dir}) {
        for (const auto& preset : list_style_presets(options.scene_options.style_dirs))
            state_.presets.push_back(preset.first);
        const std::filesystem::path scene(options.scene);
        state_.style_file = (scene.parent_path() / (scene.stem().string() + "-look.yaml")).string();
        watch_.watch({{options.scene}, {}});
        say("opening " + options.scene);
    }

    int run() {
        while (!quit_) {
            SDL_Event event;
            const bool active = state_.playing || worker_.busy() || redraw_ > 0;
            if (SDL_WaitEventTimeout(&event, active ? 10 : 40)) handle(event);
            while (SDL_PollEvent(&event)) handle(event);
            const Clock::time_point now = Clock::now();
            if (seconds_between(last_poll_, now) >= kFilePollSeconds) {
                last_poll_ = now;
                if (watch_.poll()) {
                    ++state_.files_version;
                    say("reloading: a file the scene reads changed");
                }
            }
            advance_playback(now);
            state_.interacting = dragging_ || slider_held_ ||
                                 seconds_between(last_wheel_, now) < kWheelSettleSeconds;
            take_updates();
            worker_.request(preview_request(state_));
            if (redraw_ > 0 || seconds_between(last_draw_, now) > 0.5) {
                draw();
                for (const PreviewMessage& line : shown_lines_) say(line.text, line.failed);
                shown_lines_.clear();
                last_draw_ = now;
                if (redraw_ > 0) --redraw_;
            }
        }
        // Gone at once; the worker then finishes its step and any snapshot
        // asked for before it is stopped.
        SDL_HideWindow(window_.sdl());
        return 0;
    }

  private:
    // One line per event on standard error; -q leaves only failures.
    void say(const std::string& line, bool failure = false) const {
        if (!options_.quiet || failure) std::fprintf(stderr, "preview: %s\n", line.c_str());
    }

    // A line about what the window shows is printed once it is on screen:
    // after the next draw, which the change asked for.
    void say_when_shown(const std::string& line, bool failure = false) {
        shown_lines_.push_back({line, failure});
        redraw_ = std::max(redraw_, 1);
    }

    void handle(const SDL_Event& event) {
        ImGui_ImplSDL2_ProcessEvent(&event);
        redraw_ = 3;  // ImGui settles over a few frames after input
        const ImGuiIO& io = ImGui::GetIO();
        switch (event.type) {
            case SDL_QUIT:
                quit_ = true;
                break;
            case SDL_WINDOWEVENT:
                if (event.window.event == SDL_WINDOWEVENT_CLOSE) quit_ = true;
                break;
            case SDL_KEYDOWN:
                if (!io.WantCaptureKeyboard) key(event.key.keysym, event.key.repeat != 0);
                break;
            case SDL_MOUSEBUTTONDOWN:
                dragging_ = pointer_over_image();
                break;
            case SDL_MOUSEBUTTONUP:
                dragging_ = false;
                break;
            case SDL_MOUSEMOTION:
                if (dragging_) drag(event.motion);
                break;
            case SDL_MOUSEWHEEL:
                last_wheel_ = Clock::now();
                if (pointer_over_image() && event.wheel.y != 0)
                    move_camera([&](const ViewCamera& c) {
                        return dolly(
                            c, std::pow(kDollyPerWheelStep, static_cast<float>(event.wheel.y)));
                    });
                break;
            default:
                break;
        }
    }

    // A held key repeats only the frame steps: not snapshots or prints.
    void key(const SDL_Keysym& key, bool repeat) {
        const size_t count = state_.frames.size();
        const size_t step = (key.mod & KMOD_SHIFT) ? 10 : 1;
        const bool stepping = key.sym == SDLK_LEFT || key.sym == SDLK_RIGHT;
        if (repeat && !stepping) return;
        switch (key.sym) {
            case SDLK_SPACE:
                state_.playing = !state_.playing;
                break;
            case SDLK_RIGHT:
                state_.playing = false;
                if (count) state_.frame_index = std::min(state_.frame_index + step, count - 1);
                break;
            case SDLK_LEFT:
                state_.playing = false;
                state_.frame_index -= std::min(state_.frame_index, step);
                break;
            case SDLK_HOME:
                state_.playing = false;
                state_.frame_index = 0;
                break;
            case SDLK_END:
                state_.playing = false;
                if (count) state_.frame_index = count - 1;
                break;
            case SDLK_s:
                act(PreviewAction::snapshot);
                break;
            case SDLK_c:
                act(PreviewAction::print_camera);
                break;
            case SDLK_r:
                act(PreviewAction::reset_camera);
                break;
            case SDLK_d:
                act(PreviewAction::print_defines);
                break;
            case SDLK_TAB:
                state_.show_panel = !state_.show_panel;
                break;
            case SDLK_q:
            case SDLK_ESCAPE:
                quit_ = true;
                break;
            default:
                break;
        }
    }

    // By place, not by io.WantCaptureMouse: ImGui's SDL backend learns
    // where the pointer is only at its next frame, so a click just after a
    // move would count as the panel's.
    bool pointer_over_image() const {
        int x = 0, y = 0;
        SDL_GetMouseState(&x, &y);
        return x < image_area_width_ && !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId);
    }

    // Left drag orbits; right or middle drag, or Shift with the left, pans.
    void drag(const SDL_MouseMotionEvent& motion) {
        const bool left = motion.state & SDL_BUTTON_LMASK;
        const bool other = motion.state & (SDL_BUTTON_RMASK | SDL_BUTTON_MMASK);
        if (!left && !other) return;
        const float dx = static_cast<float>(motion.xrel), dy = static_cast<float>(motion.yrel);
        if (other || (SDL_GetModState() & KMOD_SHIFT)) {
            const float height = std::max(shown_height_, 1.0f);
            move_camera([&](const ViewCamera& c) { return pan(c, -dx / height, dy / height); });
        } else {
            move_camera([&](const ViewCamera& c) {
                return orbit(c, -dx * kOrbitDegreesPerPixel, dy * kOrbitDegreesPerPixel);
            });
        }
    }

    template <typename Move>
    void move_camera(Move move) {
        if (!state_.view && !state_.scene_camera) return;  // nothing shown yet
        if (!state_.view) state_.view = view_camera_from(*state_.scene_camera);
        state_.view = move(*state_.view);
    }

    void advance_playback(Clock::time_point now) {
        if (!state_.playing || state_.frames.empty()) {
            was_playing_ = false;
            return;
        }
        if (!was_playing_) {
            play_start_ = now;
            play_first_index_ = state_.frame_index;
            was_playing_ = true;
        }
        const double fps = state_.scene ? state_.scene->output.fps : 24;
        const auto advanced = static_cast<size_t>(seconds_between(play_start_, now) * fps);
        state_.frame_index = (play_first_index_ + advanced) % state_.frames.size();
    }

    void take_updates() {
        PreviewUpdate update = worker_.take();
        if (update.scene) scene_loaded(update.scene);
        if (update.watch) watch_.watch(*update.watch);
        if (update.error && *update.error != state_.error) {
            if (!update.error->empty())
                say_when_shown("error: " + *update.error, true);
            else if (!state_.error.empty())
                say_when_shown("the scene loads again");
            state_.error = *update.error;
            redraw_ = 3;
        }
        if (update.image) {
            const PreviewImage& image = *update.image;
            window_.upload(image);
            if (!image.camera_moved) state_.scene_camera = image.camera;
            char text[96];
            std::snprintf(text, sizeof text, "%s, %.0f ms", image.step.c_str(), image.render_ms);
            state_.step = text;
            const bool live = image.step.rfind("live", 0) == 0;
            if (image.last_step && !live)
                say_when_shown("frame " + std::to_string(image.frame) + ": " + state_.step);
            redraw_ = 3;
        }
        for (const PreviewMessage& message : update.messages) {
            say(message.text, message.failed);
            state_.message = message.text;
            redraw_ = 3;
        }
    }

    void scene_loaded(const std::shared_ptr<const SceneDesc>& scene) {
        const bool first = !state_.scene;
        const int frame = state_.scene ? current_frame(state_) : INT_MIN;
        state_.scene = scene;
        state_.frames = scene->output.frames;
        if (options_.frames) {
            try {
                if (std::vector<int> asked = options_.frames(scene->output); !asked.empty())
                    state_.frames = std::move(asked);
            } catch (const std::exception& e) {
                state_.message = e.what();
                say(std::string("frames: ") + e.what() + " (showing the scene's frames)", true);
            }
        }
        auto it = std::find(state_.frames.begin(), state_.frames.end(), frame);
        state_.frame_index = it != state_.frames.end()
                                 ? static_cast<size_t>(it - state_.frames.begin())
                                 : std::min(state_.frame_index, state_.frames.size() - 1);
        if (state_.camera_index >= scene->cameras.size()) state_.camera_index = 0;
        if (!first) return;
        if (!options_.camera.empty()) {
            auto named =
                std::find_if(scene->cameras.begin(), scene->cameras.end(),
                             [&](const CameraDesc& c) { return c.name == options_.camera; });
            if (named != scene->cameras.end())
                state_.camera_index = static_cast<size_t>(named - scene->cameras.begin());
            else
                state_.message = "no camera named '" + options_.camera + "': showing '" +
                                 scene->cameras.front().name + "'";
        }
        fit_window(scene->output.width, scene->output.height);
    }

    // Room for the image at its own size beside the panel, within the screen.
    void fit_window(int width, int height) {
        SDL_Rect usable{0, 0, 1280, 800};
        SDL_GetDisplayUsableBounds(SDL_GetWindowDisplayIndex(window_.sdl()), &usable);
        const int w = std::min(width + static_cast<int>(kPanelWidth), usable.w * 9 / 10);
        const int h =
            std::min(std::max(height + static_cast<int>(kStatusHeight), 600), usable.h * 9 / 10);
        SDL_SetWindowSize(window_.sdl(), w, h);
        // Centred again, so a window grown from its first size stays on screen.
        const int display = SDL_GetWindowDisplayIndex(window_.sdl());
        SDL_SetWindowPosition(window_.sdl(), SDL_WINDOWPOS_CENTERED_DISPLAY(display),
                              SDL_WINDOWPOS_CENTERED_DISPLAY(display));
    }

    void act(PreviewAction action) {
        switch (action) {
            case PreviewAction::snapshot:
                worker_.snapshot(
                    {preview_request(state_), options_.out_dir, options_.command_line});
                state_.message =
                    "writing a snapshot of frame " + std::to_string(current_frame(state_));
                break;
            case PreviewAction::print_camera:
                print_camera();
                break;
            case PreviewAction::reset_camera:
                state_.view.reset();
                break;
            case PreviewAction::print_defines: {
                PreviewRequest request = preview_request(state_);
                if (request.camera) request.overrides.push_back(*request.camera);
                const std::string text = define_arguments(request.overrides);
                std::printf("%s\n", text.empty() ? "# no changes" : text.c_str());
                std::fflush(stdout);
                if (!text.empty()) SDL_SetClipboardText(text.c_str());
                state_.message =
                    text.empty() ? "nothing changed" : "-D arguments printed and copied";
                break;
            }
            case PreviewAction::write_style:
                write_style();
                break;
            case PreviewAction::revert_tweaks:
                state_.tweaks.clear();
                break;
            case PreviewAction::none:
                break;
        }
    }

    void print_camera() {
        if (!state_.scene || (!state_.view && !state_.scene_camera)) return;
        const ViewCamera camera =
            state_.view ? *state_.view : view_camera_from(*state_.scene_camera);
        const CameraDesc& desc = state_.scene->cameras[state_.camera_index];
        std::string text = "# the camera at frame " + std::to_string(current_frame(state_)) + "\n";
        std::string body = camera_yaml(camera, desc.name);
        // Indented under `camera:`, or as the item of `cameras:` it replaces.
        const std::string key = scene_camera_key(desc);
        const bool single = key == "camera";
        text += single ? "camera:\n" : "cameras:  # item " + key.substr(key.find('.') + 1) + "\n";
        bool first_line = true;
        size_t start = 0;
        while (start < body.size()) {
            const size_t end = body.find('\n', start);
            text += (single       ? "  "
                     : first_line ? "  - "
                                  : "    ") +
                    body.substr(start, end - start) + "\n";
            first_line = false;
            start = end + 1;
        }
        std::printf("%s", text.c_str());
        std::fflush(stdout);
        SDL_SetClipboardText(text.c_str());
        state_.message = "camera printed and copied";
    }

    void write_style() {
        if (!state_.scene) return;
        bool failed = false;
        try {
            write_file_atomically(
                state_.style_file,
                style_file_yaml(*state_.scene, state_.tweaks, options_.scene_options.style_dirs,
                                state_.style_file));
            state_.message = "wrote " + state_.style_file;
        } catch (const std::exception& e) {
            state_.message = std::string("style file not written: ") + e.what();
            failed = true;
        }
        say(state_.message, failed);
    }

    void draw() {
        ImGui_ImplOpenGL2_NewFrame();
        ImGui_ImplSDL2_NewFrame();
        ImGui::NewFrame();
        const ImVec2 size = ImGui::GetIO().DisplaySize;
        const float panel = state_.show_panel ? kPanelWidth : 0.0f;
        const float area_w = std::max(size.x - panel, 1.0f);
        image_area_width_ = static_cast<int>(area_w);
        const float area_h = std::max(size.y - kStatusHeight, 1.0f);
        float shown_w = 0;
        if (state_.scene && window_.has_image()) {
            const float w = static_cast<float>(state_.scene->output.width);
            const float h = static_cast<float>(state_.scene->output.height);
            const float scale = std::min({1.0f, area_w / w, area_h / h});
            shown_w = std::round(w * scale);
            shown_height_ = std::round(h * scale);
            window_.draw_image(shown_w, shown_height_);
        }
        draw_error(area_w, shown_w > 0 ? shown_height_ : area_h);
        draw_status(size.y);
        if (state_.show_panel) act(draw_preview_panel(state_, size.x - panel, panel, size.y));
        slider_held_ = ImGui::IsAnyItemActive();
        window_.present();
    }

    // The error over the top of the image; the last good image stays below.
    // A long one (a key's list of every key it could have been) is cut at
    // half the shown image's height: the terminal has it whole.
    void draw_error(float width, float height) {
        if (state_.error.empty()) return;
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(width, 0));
        ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0), ImVec2(width, 0.5f * height));
        ImGui::SetNextWindowBgAlpha(0.85f);
        ImGui::Begin("##error", nullptr,
                     ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                         ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                         ImGuiWindowFlags_NoInputs);
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.35f, 0.3f, 1.0f));
        ImGui::TextWrapped("%s", state_.error.c_str());
        ImGui::PopStyleColor();
        ImGui::End();
    }

    void draw_status(float height) {
        std::string text = state_.scene ? "frame " + std::to_string(current_frame(state_))
                                        : std::string("loading");
        if (!state_.step.empty())
            text += "  " + state_.step;
        else if (state_.scene && state_.error.empty())
            text += "  rendering";
        if (state_.playing) text += "  playing";
        if (!state_.message.empty()) text += "  |  " + state_.message;
        ImGui::GetForegroundDrawList()->AddText(ImVec2(8, height - kStatusHeight + 5),
                                                IM_COL32(220, 220, 220, 255), text.c_str());
    }

    const PreviewOptions& options_;
    PreviewState state_;
    Window window_;
    PreviewWorker worker_;
    FileWatch watch_;
    bool quit_ = false;
    std::vector<PreviewMessage> shown_lines_;  // said after the next draw
    bool dragging_ = false;     // a mouse button went down over the image and is held
    bool slider_held_ = false;  // an ImGui widget is being dragged or typed into
    Clock::time_point last_wheel_;
    int redraw_ = 3;
    float shown_height_ = 1;
    int image_area_width_ = 0;  // the window's width left of the panel
    Clock::time_point last_poll_ = Clock::now(), last_draw_ = Clock::now();
    bool was_playing_ = false;
    Clock::time_point play_start_;
    size_t play_first_index_ = 0;
};

}  // namespace

int run_preview(const PreviewOptions& options) {
    PreviewSession session(options);
    return session.run();
}

}  // namespace facet
