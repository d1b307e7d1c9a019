/**************************************************************************/
/*  display_server_glfw.h                                                 */
/**************************************************************************/
/* godot-area: the editor's window, through GLFW (Godot: DisplayServerX11 */
/* and friends). One fixed-size, non-resizable window with no client API  */
/* (Vulkan presents into it, drivers/vulkan/swap_chain_vk.h):             */
/*                                                                        */
/*   DisplayServerGLFW ds;                                                */
/*   ds.initialize(&err);                                                 */
/*   RD::set_extra_extensions(ds.get_required_instance_extensions(),      */
/*                            { "VK_KHR_swapchain" });                    */
/*   ...initialize the RenderingDevice...                                 */
/*   ds.create_window("godot-area editor", 1040, 600, &err);             */
/*   VkSurfaceKHR s = ds.create_surface(instance, &err);                 */
/*                                                                        */
/* Only built with GLFW (GODOT_AREA_EDITOR_WINDOW); is_available() says.  */

#pragma once

#include "core/string/ustring.h"

#include <vulkan/vulkan.h>

#include <vector>

struct GLFWwindow;

class DisplayServerGLFW {
	GLFWwindow *window = nullptr;
	bool initialized = false;

public:
	// Whether this build has GLFW at all.
	static bool is_available();

	// glfwInit() and a Vulkan check. False with r_error (e.g. no X display).
	bool initialize(String *r_error);
	// VK_KHR_surface and the platform's surface extension.
	std::vector<String> get_required_instance_extensions() const;
	// A resizable window, p_width x p_height pixels at first, at the screen's top-left corner.
	bool create_window(const String &p_title, int p_width, int p_height, String *r_error);
	// The window's framebuffer size in pixels now (0 x 0 while minimized).
	void get_framebuffer_size(int &r_width, int &r_height) const;
	VkSurfaceKHR create_surface(VkInstance p_instance, String *r_error);
	GLFWwindow *get_window() const { return window; }

	void poll_events();
	bool should_close() const;
	void finalize();

	DisplayServerGLFW() {}
	~DisplayServerGLFW() { finalize(); }
	DisplayServerGLFW(const DisplayServerGLFW &) = delete;
	DisplayServerGLFW &operator=(const DisplayServerGLFW &) = delete;
};
