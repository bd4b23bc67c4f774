// GLFW window with an OpenGL 3.3 core forward-compatible context. F11 and Alt+Enter toggle
// fullscreen here so every caller gets it; mouse deltas are raw when the cursor is captured;
// key and mouse-button press events are counted between polls.
#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdlib>
#include <utility>

#include "platform/platform.h"

namespace arc {
namespace {

bool ensure_glfw() {
  static bool ok = glfwInit() == GLFW_TRUE;
  return ok;
}

class GlfwWindow final : public Window {
 public:
  explicit GlfwWindow(const WindowDesc& d) {
    if (!ensure_glfw()) throw PlatformError("GLFW: glfwInit failed (no display?)");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    windowed_w_ = d.width;
    windowed_h_ = d.height;
    window_ = glfwCreateWindow(d.width, d.height, d.title.c_str(), nullptr, nullptr);
    if (!window_) {
      const char* msg = nullptr;
      glfwGetError(&msg);
      throw PlatformError(std::string("GLFW: glfwCreateWindow(OpenGL 3.3 core) failed (") + (msg ? msg : "?") + ")");
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(d.vsync ? 1 : 0);
    // Sticky keys: a tap shorter than one frame still reads as pressed on the next poll.
    glfwSetInputMode(window_, GLFW_STICKY_KEYS, GLFW_TRUE);
    glfwSetInputMode(window_, GLFW_STICKY_MOUSE_BUTTONS, GLFW_TRUE);
    glfwSetWindowUserPointer(window_, this);
    // Press events are counted as they arrive, so two taps between two polls are two presses.
    glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int mods) {
      auto* self = static_cast<GlfwWindow*>(glfwGetWindowUserPointer(w));
      if (action != GLFW_PRESS) return;
      count_press(self->key_presses_, key);
      if (key == GLFW_KEY_F11 || (key == GLFW_KEY_ENTER && (mods & GLFW_MOD_ALT))) self->toggle_fullscreen();
    });
    glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int button, int action, int) {
      auto* self = static_cast<GlfwWindow*>(glfwGetWindowUserPointer(w));
      if (action == GLFW_PRESS) count_press(self->mouse_presses_, button);
    });
    if (d.fullscreen) toggle_fullscreen();
    glfwGetCursorPos(window_, &last_x_, &last_y_);
  }
  ~GlfwWindow() override { glfwDestroyWindow(window_); }

  bool should_close() const override { return glfwWindowShouldClose(window_); }
  void request_close() override { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

  void poll(InputState& in) override {
    glfwPollEvents();
    in.key_presses = std::exchange(key_presses_, {});
    in.mouse_presses = std::exchange(mouse_presses_, {});
    for (int k = GLFW_KEY_SPACE; k <= GLFW_KEY_LAST && k < int(in.keys.size()); ++k)
      in.keys[k] = glfwGetKey(window_, k) == GLFW_PRESS;
    for (int b = 0; b < int(in.mouse_buttons.size()); ++b)
      in.mouse_buttons[b] = glfwGetMouseButton(window_, b) == GLFW_PRESS;
    double x = 0, y = 0;
    glfwGetCursorPos(window_, &x, &y);
    in.mouse_dx = x - last_x_;
    in.mouse_dy = y - last_y_;
    last_x_ = x;
    last_y_ = y;
    int ww = 0, wh = 0, fw = 0, fh = 0;
    glfwGetWindowSize(window_, &ww, &wh);
    glfwGetFramebufferSize(window_, &fw, &fh);
    in.mouse_x = ww > 0 ? x * fw / ww : x;
    in.mouse_y = wh > 0 ? y * fh / wh : y;
    in.gamepad_present = false;
    in.gamepad_axes.fill(0.0f);
    in.gamepad_buttons.fill(false);
    for (int j = GLFW_JOYSTICK_1; j <= GLFW_JOYSTICK_LAST; ++j) {
      GLFWgamepadstate st;
      if (!glfwJoystickIsGamepad(j) || !glfwGetGamepadState(j, &st)) continue;
      in.gamepad_present = true;
      for (int a = 0; a < 6; ++a) in.gamepad_axes[a] = st.axes[a];
      for (int b = 0; b < 15; ++b) in.gamepad_buttons[b] = st.buttons[b] == GLFW_PRESS;
      break;
    }
  }
  void swap() override { glfwSwapBuffers(window_); }
  int framebuffer_width() const override {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return w;
  }
  int framebuffer_height() const override {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return h;
  }
  bool fullscreen() const override { return glfwGetWindowMonitor(window_) != nullptr; }
  void set_vsync(bool on) override { glfwSwapInterval(on ? 1 : 0); }
  void toggle_fullscreen() override {
    if (glfwGetWindowMonitor(window_)) {
      glfwSetWindowMonitor(window_, nullptr, windowed_x_, windowed_y_, windowed_w_, windowed_h_, GLFW_DONT_CARE);
      return;
    }
    GLFWmonitor* m = glfwGetPrimaryMonitor();
    const GLFWvidmode* mode = m ? glfwGetVideoMode(m) : nullptr;
    if (!mode) return;
    glfwGetWindowPos(window_, &windowed_x_, &windowed_y_);
    glfwGetWindowSize(window_, &windowed_w_, &windowed_h_);
    glfwSetWindowMonitor(window_, m, 0, 0, mode->width, mode->height, mode->refreshRate);
  }
  void set_mouse_captured(bool captured) override {
    glfwSetInputMode(window_, GLFW_CURSOR, captured ? GLFW_CURSOR_DISABLED : GLFW_CURSOR_NORMAL);
    if (glfwRawMouseMotionSupported())
      glfwSetInputMode(window_, GLFW_RAW_MOUSE_MOTION, captured ? GLFW_TRUE : GLFW_FALSE);
    glfwGetCursorPos(window_, &last_x_, &last_y_);
  }
  double time_seconds() const override { return glfwGetTime(); }

 private:
  template <size_t N>
  static void count_press(std::array<uint8_t, N>& counts, int code) {
    if (code >= 0 && size_t(code) < N && counts[size_t(code)] < 255) ++counts[size_t(code)];
  }

  GLFWwindow* window_ = nullptr;
  std::array<uint8_t, 512> key_presses_{};  // since the last poll, filled by the callbacks
  std::array<uint8_t, 8> mouse_presses_{};
  double last_x_ = 0, last_y_ = 0;
  int windowed_x_ = 64, windowed_y_ = 64, windowed_w_ = 1280, windowed_h_ = 720;
};

}  // namespace

std::unique_ptr<Window> open_window(const WindowDesc& desc) { return std::make_unique<GlfwWindow>(desc); }

bool display_available() {
  const char* x = std::getenv("DISPLAY");
  const char* w = std::getenv("WAYLAND_DISPLAY");
  if ((!x || !*x) && (!w || !*w)) return false;
  return ensure_glfw();
}

}  // namespace arc
