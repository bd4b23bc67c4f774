// Poisoned header: simulation code (engine/core, assets, particles, replay, game/sim)
// must not see OpenGL, GLFW or EGL. Move this include to engine/gfx or engine/platform.
#error "simulation code must not include <GL/glext.h>"
