// The OpenGL3 renderer backend of Dear ImGui 1.86 as Debian ships it, with GL loaded through
// libepoxy like the rest of Arcfire: IMGUI_IMPL_OPENGL_LOADER_CUSTOM skips the backend's own
// gl3w loader, whose second set of GL entry points would shadow epoxy's.
#include <epoxy/gl.h>
#define IMGUI_IMPL_OPENGL_LOADER_CUSTOM
#include "imgui_impl_opengl3.cpp"
