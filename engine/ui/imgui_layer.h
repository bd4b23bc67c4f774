// ui/imgui_layer.h — Dear ImGui panels drawn over a GLFW window's frame.
//
// The tool panels (the effect workbench, the in-game F1 panel) are Dear ImGui windows; this
// module owns the ImGui context and its GLFW and OpenGL3 backends, so no other module includes
// a backend. It attaches to the window whose GL context is current (platform's GlfwWindow
// makes its context current and keeps it so), and chains GLFW's input callbacks: the window
// still sees every key and click. Callers ask wants_mouse()/wants_keyboard() before acting on
// input the panel took.
//
// One ImGuiLayer is made after open_window(). Each frame, after the window's poll, begin_frame()
// starts the panels' frame (the ImGui::Begin ... ImGui::End calls come between), and once the
// renderer has drawn the scene, end_frame() draws the panels over it, before the swap
// (game/workbench/workbench_window.cpp runs this loop).
#pragma once

namespace arc {

class ImGuiLayer {
 public:
  // Throws PlatformError when no GLFW window's context is current.
  ImGuiLayer();
  ~ImGuiLayer();
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  void begin_frame();  // after the window's poll: ImGui::* calls are valid until end_frame()
  void end_frame();    // draws the panels into the window's default framebuffer
  bool wants_mouse() const;     // the cursor is over a panel or a panel widget is held
  bool wants_keyboard() const;  // a text field has the keyboard
};

}  // namespace arc
