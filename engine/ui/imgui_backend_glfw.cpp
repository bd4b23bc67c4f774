// The GLFW platform backend of Dear ImGui 1.86 as Debian ships it (not a copy: the package's
// source file, compiled in this translation unit).
#include "imgui_impl_glfw.cpp"
