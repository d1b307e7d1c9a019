/**************************************************************************/
/*  display_server_glfw.cpp                                               */
/**************************************************************************/
/* godot-area: see display_server_glfw.h.                                 */

#include "drivers/glfw/display_server_glfw.h"

#include "core/error/error_macros.h"

#ifdef GODOT_AREA_EDITOR_WINDOW
#define GLFW_INCLUDE_NONE
#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#endif

#include <cstdio>

bool DisplayServerGLFW::is_available() {
#ifdef GODOT_AREA_EDITOR_WINDOW
	return true;
#else
	return false;
#endif
}

#ifdef GODOT_AREA_EDITOR_WINDOW

static void _glfw_error(int p_code, const char *p_message) {
	fprintf(stderr, "GLFW error %d: %s\n", p_code, p_message);
}

bool DisplayServerGLFW::initialize(String *r_error) {
	glfwSetErrorCallback(_glfw_error);
	if (!glfwInit()) {
		*r_error = "GLFW could not initialize (is DISPLAY set to a running X server?)";
		return false;
	}
	initialized = true;
	if (!glfwVulkanSupported()) {
		*r_error = "GLFW found no Vulkan loader that can present to this display.";
		finalize();
		return false;
	}
	return true;
}

std::vector<String> DisplayServerGLFW::get_required_instance_extensions() const {
	std::vector<String> out;
	if (!initialized) {
		return out;
	}
	uint32_t count = 0;
	const char **names = glfwGetRequiredInstanceExtensions(&count);
	for (uint32_t i = 0; names && i < count; i++) {
		out.push_back(names[i]);
	}
	return out;
}

bool DisplayServerGLFW::create_window(const String &p_title, int p_width, int p_height, String *r_error) {
	ERR_FAIL_COND_V_MSG(!initialized, false, "DisplayServerGLFW: initialize() first.");
	ERR_FAIL_COND_V_MSG(window, false, "DisplayServerGLFW: the window already exists.");
	glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
	glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
	window = glfwCreateWindow(p_width, p_height, p_title.c_str(), nullptr, nullptr);
	if (!window) {
		*r_error = "glfwCreateWindow failed.";
		return false;
	}
	glfwSetWindowPos(window, 0, 0);
	glfwFocusWindow(window);
	return true;
}

void DisplayServerGLFW::get_framebuffer_size(int &r_width, int &r_height) const {
	r_width = 0;
	r_height = 0;
	if (window) {
		glfwGetFramebufferSize(window, &r_width, &r_height);
	}
}

VkSurfaceKHR DisplayServerGLFW::create_surface(VkInstance p_instance, String *r_error) {
	ERR_FAIL_NULL_V_MSG(window, VK_NULL_HANDLE, "DisplayServerGLFW: no window.");
	VkSurfaceKHR surface = VK_NULL_HANDLE;
	VkResult res = glfwCreateWindowSurface(p_instance, window, nullptr, &surface);
	if (res != VK_SUCCESS) {
		*r_error = vformat("glfwCreateWindowSurface failed (VkResult %d).", res);
		return VK_NULL_HANDLE;
	}
	return surface;
}

void DisplayServerGLFW::poll_events() {
	glfwPollEvents();
}

bool DisplayServerGLFW::should_close() const {
	return !window || glfwWindowShouldClose(window);
}

void DisplayServerGLFW::finalize() {
	if (window) {
		glfwDestroyWindow(window);
		window = nullptr;
	}
	if (initialized) {
		glfwTerminate();
		initialized = false;
	}
}

#else // No GLFW in this build.

bool DisplayServerGLFW::initialize(String *r_error) {
	*r_error = "this build has no window support (install libglfw3-dev and libimgui-dev, then rebuild)";
	return false;
}
std::vector<String> DisplayServerGLFW::get_required_instance_extensions() const {
	return std::vector<String>();
}
bool DisplayServerGLFW::create_window(const String &p_title, int p_width, int p_height, String *r_error) {
	*r_error = "no window support in this build";
	return false;
}
void DisplayServerGLFW::get_framebuffer_size(int &r_width, int &r_height) const {
	r_width = 0;
	r_height = 0;
}
VkSurfaceKHR DisplayServerGLFW::create_surface(VkInstance p_instance, String *r_error) {
	*r_error = "no window support in this build";
	return VK_NULL_HANDLE;
}
void DisplayServerGLFW::poll_events() {}
bool DisplayServerGLFW::should_close() const {
	return true;
}
void DisplayServerGLFW::finalize() {}

#endif
