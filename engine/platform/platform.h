// platform/platform.h — windows and GL contexts. The only module besides gfx that sees GL.
//
// Two backends behind one interface:
//   GlfwWindow   a resizable window with an OpenGL 3.3 core context, keyboard, mouse, gamepads.
//   EglHeadless  a surfaceless EGL context (EGL_MESA_platform_surfaceless, then
//                EGL_EXT_platform_device) rendering into an FBO owned by gfx.
// Both make the context current and load GL through libepoxy, so the renderer is the same.
// Creation failures throw arc::PlatformError naming the step that failed.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace arc {

struct PlatformError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Device codes by the names bindings files use (GLFW's names without the GLFW_KEY_ prefix:
// A, F12, SPACE, LEFT_SHIFT, MOUSE_LEFT, ...; gamepad LEFT_X, RIGHT_BUMPER, ...); −1 for an
// unknown name. Keys and mouse buttons share one code space: mouse button n is
// kMouseButtonBase + n. input_names.cpp.
constexpr int kMouseButtonBase = 1000;
int key_code(std::string_view name);
int gamepad_axis_code(std::string_view name);
int gamepad_button_code(std::string_view name);
// The names back from codes (the first name of a code); "" for a code without one.
std::string key_name(int code);
std::string gamepad_button_name(int code);

// Raw device state sampled once per rendered frame; the game quantises it into InputFrames.
struct InputState {
  std::array<bool, 512> keys{};         // GLFW key codes
  std::array<bool, 8> mouse_buttons{};
  // Press events since the last poll (a key tapped twice within one frame counts 2), saturating.
  std::array<uint8_t, 512> key_presses{};
  std::array<uint8_t, 8> mouse_presses{};
  double mouse_dx = 0, mouse_dy = 0;    // pixels moved since last poll
  double mouse_x = 0, mouse_y = 0;      // the cursor in framebuffer pixels from the top left (menus)
  bool gamepad_present = false;
  std::array<float, 6> gamepad_axes{};  // GLFW_GAMEPAD_AXIS_*
  std::array<bool, 15> gamepad_buttons{};
};

struct WindowDesc {
  int width = 1280;
  int height = 720;
  std::string title = "Arcfire";
  bool vsync = true;
  bool fullscreen = false;
};

class Window {
 public:
  virtual ~Window() = default;
  virtual bool should_close() const = 0;
  virtual void request_close() = 0;
  virtual void poll(InputState& input) = 0;  // fills input, resets per-frame deltas
  virtual void swap() = 0;
  virtual int framebuffer_width() const = 0;
  virtual int framebuffer_height() const = 0;
  virtual void toggle_fullscreen() = 0;
  virtual bool fullscreen() const = 0;
  virtual void set_vsync(bool on) = 0;  // the swap interval: 1 with, 0 without
  virtual void set_mouse_captured(bool captured) = 0;
  virtual double time_seconds() const = 0;  // wall clock for the frame loop only, never simulation
};

// Opens a window; throws PlatformError if there is no display or no GL 3.3 context.
std::unique_ptr<Window> open_window(const WindowDesc& desc);
bool display_available();  // a quick check: $DISPLAY or $WAYLAND_DISPLAY and glfwInit succeeds

// A current surfaceless GL context. Rendering goes to an FBO made by gfx.
class HeadlessContext {
 public:
  virtual ~HeadlessContext() = default;
  virtual std::string description() const = 0;  // "EGL 1.5 surfaceless, OpenGL 4.5 (llvmpipe)"
};
std::unique_ptr<HeadlessContext> create_headless_context();

}  // namespace arc
