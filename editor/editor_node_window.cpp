/**************************************************************************/
/*  editor_node_window.cpp                                                */
/**************************************************************************/
/* godot-area: EditorNode::run(), the editor window's main loop (see      */
/* editor_node.h). Input: GLFW callbacks queue mouse and key events with  */
/* the cursor position at the time of the event, so a fast synthetic     */
/* press-move-release (xdotool) is replayed in order even when a frame    */
/* takes seconds (lavapipe renders on the CPU). The 3D viewport gets the  */
/* events inside its rectangle; ImGui gets everything through its own     */
/* GLFW backend.                                                          */

#include "editor/editor_node.h"

#ifdef GODOT_AREA_EDITOR_WINDOW

#include "core/error/error_macros.h"
#include "core/object/undo_redo.h"
#include "drivers/glfw/display_server_glfw.h"
#include "drivers/png/png_writer.h"
#include "drivers/vulkan/swap_chain_vk.h"
#include "editor/editor_inspector.h"
#include "editor/editor_properties.h"
#include "editor/editor_resource_preview.h"
#include "editor/plugins/node_3d_editor_plugin.h"
#include "editor/resource_preview_blit_vk.h"
#include "editor/scene_tree_dock.h"
#include "editor/scene_tree_editor.h"
#include "editor/viewport_blit_vk.h"
#include "modules/register_module_types.h"
#include "scene/3d/node_3d.h"
#include "scene/main/godot_instance.h"
#include "scene/main/node.h"
#include "scene/main/scene_tree.h"
#include "scene/resources/resource_format_text.h"
#include "scene/resources/texture.h"
#include "servers/rendering/rendering_device.h"

#define GLFW_INCLUDE_NONE
#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>

#include <cstdio>
#include <cstring>
#include <vector>

namespace {

struct InputEvent {
	enum Type {
		MOUSE_BUTTON,
		MOUSE_MOTION,
		SCROLL,
		KEY,
	};
	Type type = MOUSE_MOTION;
	int button = 0; // GLFW mouse button or key.
	int action = 0;
	int mods = 0;
	double x = 0, y = 0; // Window pixels (scroll: offsets).
};

std::vector<InputEvent> input_queue;
double cursor_x = 0, cursor_y = 0;

void _on_cursor(GLFWwindow *p_window, double p_x, double p_y) {
	cursor_x = p_x;
	cursor_y = p_y;
	input_queue.push_back({ InputEvent::MOUSE_MOTION, 0, 0, 0, p_x, p_y });
}

void _on_mouse_button(GLFWwindow *p_window, int p_button, int p_action, int p_mods) {
	input_queue.push_back({ InputEvent::MOUSE_BUTTON, p_button, p_action, p_mods, cursor_x, cursor_y });
}

void _on_scroll(GLFWwindow *p_window, double p_dx, double p_dy) {
	input_queue.push_back({ InputEvent::SCROLL, 0, 0, 0, cursor_x, p_dy });
}

void _on_key(GLFWwindow *p_window, int p_key, int p_scancode, int p_action, int p_mods) {
	input_queue.push_back({ InputEvent::KEY, p_key, p_action, p_mods, cursor_x, cursor_y });
}

void _check_vk(VkResult p_result) {
	if (p_result != VK_SUCCESS) {
		ERR_PRINT(vformat("Dear ImGui's Vulkan backend: VkResult %d.", p_result));
	}
}

// p_node's path relative to p_root ("." for the root itself), as --select takes it.
String _path_in_scene(const Node *p_root, const Node *p_node) {
	if (p_node == p_root) {
		return ".";
	}
	String path;
	for (const Node *n = p_node; n && n != p_root; n = n->get_parent()) {
		path = path.empty() ? String(n->get_name()) : String(n->get_name()) + "/" + path;
	}
	return path;
}

class EditorSession {
public:
	EditorNode::Options options;
	FILE *log = nullptr;
	SceneTree *tree = nullptr;
	Node *scene = nullptr;
	UndoRedo undo_redo;
	SceneTreeDock dock;
	SceneTreeEditor tree_editor;
	EditorInspector inspector;
	Node3DEditorViewport viewport;
	EditorNode::Layout layout = EditorNode::compute_layout(EditorNode::WINDOW_WIDTH, EditorNode::WINDOW_HEIGHT);
	ViewportBlitVK blit;
	ResourcePreviewBlitVK preview; // The inspector's texture thumbnail.
	String preview_logged; // "property w h x y" of the last preview written to the test log.
	String preview_property; // The row the preview was queued for this frame.
	String pending_screenshot; // F12: written from the next presented frame.
	bool log_layer_cells = false; // After a layout change: log the first layer grid's cells once.
	Node *shown_selection = nullptr;
	uint64_t seen_undo_version = 0;
	uint64_t seen_dock_version = 0;
	int screenshot_count = 0;
	String status_message;
	int load_problems = 0; // Distinct problems the scene's load counted (content kept as placeholders/text).
	bool overwrite_confirmed = false;
	bool quit = false;
	bool viewport_hovered = false;
	bool window_captured = false;
	bool window_capture_requested = false; // F11.
	bool viewport_pressed[3] = { false, false, false };
	// What the scene loader reported (one line per distinct problem: what was kept as a
	// placeholder or as text, what could not be applied), shown in the Output dock.
	std::vector<String> load_report;

	void log_line(const String &p_text) {
		if (log) {
			fprintf(log, "%s\n", p_text.c_str());
			fflush(log);
		}
	}

	void log_handles() {
		for (const Node3DEditorViewport::HandleInfo &h : viewport.get_handles()) {
			log_line(vformat("handle %d %s %.1f %.1f", h.id, h.name.c_str(), h.position.x + layout.viewport.x, h.position.y + layout.viewport.y));
		}
	}

	void log_state(const char *p_reason) {
		Node *sel = dock.get_selected();
		if (sel) {
			bool valid = false;
			Variant size = sel->get("area_size", &valid);
			if (valid) {
				log_line(vformat("property %s area_size %s (%s)", String(sel->get_name()).c_str(), size.stringify().c_str(), p_reason));
			}
		}
	}

	void sync_selection() {
		Node *sel = dock.get_selected();
		if (sel != shown_selection) {
			shown_selection = sel;
			viewport.set_selected(sel);
			inspector.edit(sel);
			log_line(vformat("select %s", sel ? _path_in_scene(scene, sel).c_str() : "<none>"));
			log_handles();
			log_state("select");
		}
	}

	void undo(bool p_redo) {
		viewport.cancel_drag();
		String name = p_redo ? String() : undo_redo.get_current_action_name();
		bool ok = p_redo ? undo_redo.redo() : undo_redo.undo();
		if (p_redo && ok) {
			name = undo_redo.get_current_action_name();
		}
		status_message = ok ? vformat("%s: %s", p_redo ? "Redo" : "Undo", name.c_str()) : String(p_redo ? "Nothing to redo" : "Nothing to undo");
		log_line(vformat("%s %s %s", p_redo ? "redo" : "undo", ok ? "ok" : "none", name.c_str()));
		viewport.mark_scene_changed();
		log_state(p_redo ? "redo" : "undo");
	}

	void save() {
		String error;
		if (load_problems > 0 && !overwrite_confirmed && options.save_path == options.scene_path) {
			// Never overwrite such a file silently: the first Ctrl+S explains, the second saves.
			overwrite_confirmed = true;
			status_message = vformat("The scene loaded with %d kinds of content this engine keeps but does not run (see the warnings); Ctrl+S again writes it back to %s.", load_problems, options.save_path.c_str());
			log_line("save needs confirmation " + options.save_path);
			return;
		}
		if (ResourceFormatText::save_scene(scene, options.save_path, &error)) {
			status_message = "Saved " + options.save_path;
			log_line("save ok " + options.save_path);
		} else {
			status_message = "Save failed: " + error;
			log_line("save error " + error);
		}
	}

	// F12: the viewport exactly as shown (scene, gizmos, the panel's caption), cropped from the
	// next presented frame, which the swapchain reads back.
	void screenshot() {
		pending_screenshot = vformat("%s_%d.png", options.screenshot_prefix.empty() ? "editor_viewport" : options.screenshot_prefix.c_str(), screenshot_count++);
	}

	void write_screenshot(const std::vector<uint8_t> &p_window, int p_width, int p_height) {
		const String path = pending_screenshot;
		pending_screenshot.clear();
		const EditorNode::Rect &r = layout.viewport;
		String error;
		if (p_window.size() != size_t(p_width) * p_height * 4 || r.x + r.width > p_width || r.y + r.height > p_height) {
			error = "the window could not be read back";
		} else {
			std::vector<uint8_t> crop(size_t(r.width) * r.height * 4);
			for (int y = 0; y < r.height; y++) {
				memcpy(&crop[size_t(y) * r.width * 4], &p_window[(size_t(r.y + y) * p_width + r.x) * 4], size_t(r.width) * 4);
			}
			if (PNGWriter::save_rgba8(crop, r.width, r.height, path, &error)) {
				status_message = "Wrote " + path;
				log_line("screenshot " + path);
				return;
			}
		}
		status_message = "Screenshot failed: " + error;
		log_line("screenshot error " + error);
	}

	void handle_key(const InputEvent &p_e) {
		if (p_e.action != GLFW_PRESS) {
			return;
		}
		const bool ctrl = p_e.mods & GLFW_MOD_CONTROL;
		const bool shift = p_e.mods & GLFW_MOD_SHIFT;
		if (ImGui::GetIO().WantTextInput && p_e.button != GLFW_KEY_F12) {
			return; // Typing in a field.
		}
		if (ctrl && p_e.button == GLFW_KEY_Z) {
			undo(shift);
		} else if (ctrl && p_e.button == GLFW_KEY_Y) {
			undo(true);
		} else if (ctrl && p_e.button == GLFW_KEY_S) {
			save();
		} else if (ctrl && p_e.button == GLFW_KEY_Q) {
			quit = true;
		} else if (p_e.button == GLFW_KEY_F11) {
			window_capture_requested = true;
		} else if (p_e.button == GLFW_KEY_F12) {
			screenshot();
		} else if (p_e.button == GLFW_KEY_ESCAPE) {
			viewport.cancel_drag();
		}
	}

	static bool _popup_open() {
		return ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel);
	}

	void handle_mouse(const InputEvent &p_e) {
		Vector2 local((real_t)p_e.x - layout.viewport.x, (real_t)p_e.y - layout.viewport.y);
		bool inside = local.x >= 0 && local.y >= 0 && local.x < layout.viewport.width && local.y < layout.viewport.height;
		if (p_e.type == InputEvent::MOUSE_MOTION) {
			viewport.mouse_motion(local);
		} else if (p_e.type == InputEvent::SCROLL) {
			if (inside && !_popup_open()) {
				viewport.zoom((real_t)p_e.y);
			}
		} else if (p_e.type == InputEvent::MOUSE_BUTTON) {
			int b = p_e.button == GLFW_MOUSE_BUTTON_LEFT ? Node3DEditorViewport::MOUSE_BUTTON_LEFT : (p_e.button == GLFW_MOUSE_BUTTON_RIGHT ? Node3DEditorViewport::MOUSE_BUTTON_RIGHT : (p_e.button == GLFW_MOUSE_BUTTON_MIDDLE ? Node3DEditorViewport::MOUSE_BUTTON_MIDDLE : -1));
			if (b < 0) {
				return;
			}
			if (p_e.action == GLFW_PRESS) {
				if (!inside || _popup_open()) {
					return; // A combo or menu over the viewport takes the click.
				}
				viewport_pressed[b] = true;
				if (viewport.mouse_button(b, true, local, p_e.mods & GLFW_MOD_SHIFT)) {
					dock.select(viewport.get_selected());
				}
			} else if (viewport_pressed[b]) {
				viewport_pressed[b] = false;
				bool was_dragging = viewport.is_dragging_handle();
				if (viewport.mouse_button(b, false, local, p_e.mods & GLFW_MOD_SHIFT)) {
					dock.select(viewport.get_selected());
				}
				if (was_dragging) {
					log_state("drag_end");
					log_handles();
				}
			}
		}
	}

	void draw_inspector() {
		inspector.refresh();
		if (!inspector.get_edited_object()) {
			ImGui::TextDisabled("Select a node.");
			return;
		}
		Node *node = Object::cast_to<Node>(inspector.get_edited_object());
		ImGui::Text("%s  (%s)", node ? String(node->get_name()).c_str() : "", inspector.get_edited_object()->get_class().c_str());
		ImGui::Separator();
		ImGui::BeginChild("rows");
		// One label column for all rows: as wide as the longest label, at most 45 % of the panel.
		std::vector<float> label_widths;
		for (int i = 0; i < inspector.get_row_count(); i++) {
			label_widths.push_back(EditorProperties::measure_label(inspector.get_row(i)));
		}
		const float label_width = EditorInspector::get_label_column_width(label_widths, ImGui::GetContentRegionAvail().x, ImGui::GetStyle().ItemSpacing.x * 2);
		String group;
		bool group_open = true;
		for (int i = 0; i < inspector.get_row_count(); i++) {
			const EditorPropertyRow &row = inspector.get_row(i);
			if (row.group != group) {
				group = row.group;
				group_open = group.empty() || ImGui::CollapsingHeader(group.c_str(), ImGuiTreeNodeFlags_DefaultOpen);
			}
			if (!group_open) {
				continue;
			}
			if (!row.subgroup.empty() && (i == 0 || inspector.get_row(i - 1).subgroup != row.subgroup)) {
				ImGui::TextDisabled("%s", row.subgroup.c_str());
			}
			Variant value = inspector.get_row_value(i);
			Variant new_value;
			EditorProperties::Result r = EditorProperties::draw_row(row, value, new_value, label_width);
			if (r.changed) {
				if (!inspector.set_row_value(i, new_value, r.active)) {
					status_message = inspector.get_last_error();
				} else if (!r.active) {
					log_line(vformat("edit %s %s %s", node ? String(node->get_name()).c_str() : "<object>", row.property.c_str(), inspector.get_row_value(i).stringify().c_str()));
				}
				viewport.mark_scene_changed();
			}
			if (r.deactivated) {
				inspector.end_merge();
			}
		}
		ImGui::EndChild();
	}

	void draw_status() {
		double total = 0;
		String passes;
		for (const auto &p : viewport.get_profile()) {
			passes += vformat("  %s %.2f", p.first.c_str(), p.second);
			total += p.second;
		}
		ImGui::Text("GPU %.2f ms:%s   |  %s", total, passes.c_str(), status_message.c_str());
	}

	void draw_output() {
		if (!load_report.empty()) {
			// Wrapped like Godot's Output dock: a report line never runs past the panel.
			ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.8f, 0.3f, 1.0f));
			ImGui::TextWrapped("Scene load report: %d line(s) (kept as placeholders or text, or not applied):", (int)load_report.size());
			ImGui::PopStyleColor();
			for (const String &line : load_report) {
				ImGui::Bullet();
				ImGui::TextWrapped("%s", line.c_str());
			}
			ImGui::Separator();
		}
		ImGui::Text("GPU time per pass (last frame, ms):");
		double total = 0;
		for (const auto &p : viewport.get_profile()) {
			ImGui::BulletText("%-16s %9.3f", p.first.c_str(), p.second);
			total += p.second;
		}
		ImGui::BulletText("%-16s %9.3f", "total", total);
		ImGui::Separator();
		ImGui::TextDisabled("Viewport: right/middle drag orbits, Shift+drag pans, wheel zooms;");
		ImGui::TextDisabled("click a light to select it, drag its handles. Ctrl+Z / Ctrl+Shift+Z,");
		ImGui::TextDisabled("Ctrl+S saves %s, F12 writes a screenshot.", options.save_path.c_str());
		ImGui::Text("Undo history: %d action(s), at %d: %s", undo_redo.get_history_count(), undo_redo.get_current_action(), undo_redo.get_current_action_name().c_str());
	}

	void draw_panels() {
		const ImGuiWindowFlags fixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings;
		auto place = [](const EditorNode::Rect &p_r) {
			ImGui::SetNextWindowPos(ImVec2((float)p_r.x, (float)p_r.y));
			ImGui::SetNextWindowSize(ImVec2((float)p_r.width, (float)p_r.height));
		};
		place(layout.scene);
		ImGui::Begin("Scene", nullptr, fixed);
		tree_editor.draw();
		ImGui::End();

		const EditorNode::Rect &v = layout.viewport;
		place(v);
		ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
		ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
		ImGui::Begin("Viewport", nullptr, fixed | ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground | ImGuiWindowFlags_NoBringToFrontOnFocus);
		// The engine's frame, sampled on the GPU (ViewportBlitVK) under the caption; the button only
		// takes the mouse.
		blit.add_to_draw_list(ImGui::GetWindowDrawList(), (float)v.x, (float)v.y, (float)v.width, (float)v.height);
		ImGui::InvisibleButton("##viewport", ImVec2((float)v.width, (float)v.height), ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight | ImGuiButtonFlags_MouseButtonMiddle);
		viewport_hovered = ImGui::IsWindowHovered(ImGuiHoveredFlags_AllowWhenBlockedByActiveItem);
		ImGui::SetCursorPos(ImVec2(6, 4));
		ImGui::TextColored(ImVec4(1, 1, 1, 0.8f), "Perspective  %s", viewport.is_dragging_handle() ? "(dragging: lighting updates on release)" : "");
		ImGui::End();
		ImGui::PopStyleVar(2);

		if (layout.output.height > 0) {
			place(layout.output);
			ImGui::Begin("Output", nullptr, fixed);
			draw_output();
			ImGui::End();
		}

		place(layout.inspector);
		ImGui::Begin("Inspector", nullptr, fixed);
		draw_inspector();
		ImGui::End();

		place(layout.status);
		ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(6, 4));
		ImGui::Begin("Status", nullptr, fixed | ImGuiWindowFlags_NoDecoration);
		draw_status();
		ImGui::End();
		ImGui::PopStyleVar();
	}
};

} // namespace

int EditorNode::run(const Options &p_options) {
	EditorSession s;
	s.options = p_options;
	if (!p_options.test_log.empty()) {
		s.log = fopen(p_options.test_log.c_str(), "w");
		if (!s.log) {
			fprintf(stderr, "godot-area editor: cannot write the test log '%s'\n", p_options.test_log.c_str());
			return 2;
		}
	}
	String error;
	DisplayServerGLFW display;
	if (!display.initialize(&error)) {
		fprintf(stderr, "godot-area editor: %s\n", error.c_str());
		s.log_line("exit error " + error);
		return 1;
	}
	RenderingDevice::set_extra_extensions(display.get_required_instance_extensions(), { VK_KHR_SWAPCHAIN_EXTENSION_NAME });
	GodotInstance engine;
	if (!engine.start(GodotInstance::BACKEND_RD, &error)) {
		fprintf(stderr, "godot-area editor: %s\n", error.c_str());
		s.log_line("exit error " + error);
		return 1;
	}
	initialize_modules();
	int code = 0;
	{
		SceneTree tree;
		s.tree = &tree;
		{
			// The loader's warnings are the load report (it counts each kind of problem once).
			ErrorHandlerList report_handler;
			report_handler.callback = [&s](ErrorHandlerType, const String &p_text) { s.load_report.push_back(p_text); };
			add_error_handler(&report_handler);
			s.scene = GodotInstance::load_scene(p_options.scene_path, &error);
			remove_error_handler(&report_handler);
		}
		s.load_problems = s.scene ? ResourceFormatText::get_last_load_problem_count() : 0;
		for (const String &line : s.load_report) {
			s.log_line("load " + line);
		}
		if (!s.scene) {
			fprintf(stderr, "godot-area editor: cannot load scene '%s': %s\n", p_options.scene_path.empty() ? "<embedded demo>" : p_options.scene_path.c_str(), error.c_str());
			code = 2;
		}
		SwapChainVK swap_chain;
		VkDescriptorPool pool = VK_NULL_HANDLE;
		RenderingDevice::VulkanHandles vk = RenderingDevice::get_singleton()->get_vulkan_handles();
		if (!code) {
			tree.get_root()->add_child(s.scene);
			s.dock.set_undo_redo(&s.undo_redo);
			s.dock.set_edited_scene(s.scene);
			s.inspector.set_undo_redo(&s.undo_redo);
			s.tree_editor.set_dock(&s.dock);
			s.viewport.set_event_callback([&s](const String &p_text) { s.log_line(p_text); });
			s.viewport.setup(&tree, s.scene, s.layout.viewport.width, s.layout.viewport.height, &s.undo_redo);
			s.viewport.set_gpu_display(true); // Sampled by ViewportBlitVK, never read back.
			if (!p_options.select_path.empty()) {
				Node *n = s.scene->get_node_or_null(p_options.select_path);
				if (!n) {
					fprintf(stderr, "godot-area editor: --select: the scene has no node '%s'\n", p_options.select_path.c_str());
					code = 2;
				} else {
					s.dock.select(n);
				}
			}
		}
		if (!code && !display.create_window("godot-area editor - " + (p_options.scene_path.empty() ? String("demo") : p_options.scene_path), WINDOW_WIDTH, WINDOW_HEIGHT, &error)) {
			fprintf(stderr, "godot-area editor: %s\n", error.c_str());
			code = 1;
		}
		if (!code) {
			VkSurfaceKHR surface = display.create_surface((VkInstance)vk.instance, &error);
			if (!surface || !swap_chain.create(vk, surface, WINDOW_WIDTH, WINDOW_HEIGHT, &error)) {
				fprintf(stderr, "godot-area editor: %s\n", error.c_str());
				code = 1;
			}
		}
		if (!code) {
			VkDescriptorPoolSize size = { VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 16 };
			VkDescriptorPoolCreateInfo dpci = { VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO };
			dpci.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
			dpci.maxSets = 16;
			dpci.poolSizeCount = 1;
			dpci.pPoolSizes = &size;
			vkCreateDescriptorPool((VkDevice)vk.device, &dpci, nullptr, &pool);
			GLFWwindow *window = display.get_window();
			// Ours first: ImGui's backend chains to the callbacks installed before it.
			glfwSetCursorPosCallback(window, _on_cursor);
			glfwSetMouseButtonCallback(window, _on_mouse_button);
			glfwSetScrollCallback(window, _on_scroll);
			glfwSetKeyCallback(window, _on_key);
			IMGUI_CHECKVERSION();
			ImGui::CreateContext();
			ImGui::GetIO().IniFilename = nullptr; // Fixed layout, nothing written next to the scene.
			ImGui::StyleColorsDark();
			ImGui_ImplGlfw_InitForVulkan(window, true);
			ImGui_ImplVulkan_InitInfo info = {};
			info.Instance = (VkInstance)vk.instance;
			info.PhysicalDevice = (VkPhysicalDevice)vk.physical_device;
			info.Device = (VkDevice)vk.device;
			info.QueueFamily = vk.queue_family;
			info.Queue = (VkQueue)vk.queue;
			info.DescriptorPool = pool;
			info.MinImageCount = swap_chain.get_min_image_count();
			info.ImageCount = swap_chain.get_image_count();
			info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
			info.CheckVkResultFn = _check_vk;
			ImGui_ImplVulkan_Init(&info, swap_chain.get_render_pass());
			if (!s.blit.create(RenderingDevice::get_singleton(), swap_chain.get_render_pass(), &error)) {
				fprintf(stderr, "godot-area editor: %s\n", error.c_str());
				s.quit = true;
				code = 1;
			}
			if (!s.quit && !s.preview.create(RenderingDevice::get_singleton(), swap_chain.get_render_pass(), &error)) {
				fprintf(stderr, "godot-area editor: %s\n", error.c_str());
				s.quit = true;
				code = 1;
			}
			// Resource rows: the first texture row of a frame gets the thumbnail (one preview on screen).
			EditorProperties::resource_preview_callback = [&s](const EditorPropertyRow &p_row, const Variant &p_value) {
				if (s.preview_property.empty()) {
					s.preview.draw(Object::cast_to<Texture2D>(p_value.get_object()));
					s.preview_property = p_row.property;
				}
			};
			// A path typed into a resource row resolves as the scene's own ext_resource paths do.
			EditorProperties::resource_load_callback = [&s](const String &p_path, const String &p_type, String *r_error) -> Variant {
				Variant v = EditorResourcePreview::load_for_property(p_path, s.options.scene_path, p_type, r_error);
				if (v.get_object()) {
					s.log_line(vformat("resource_loaded %s %s", p_path.c_str(), v.get_object()->get_class().c_str()));
				}
				return v;
			};
			// Layer-grid cells (window pixels) for the test log, once after each layout change.
			EditorProperties::layer_cell_callback = [&s](const String &p_property, int p_bit, float p_x, float p_y) {
				if (s.log_layer_cells && p_bit < 2) {
					Node *sel = s.dock.get_selected();
					s.log_line(vformat("layer_cell %s %s %d %.1f %.1f", sel ? String(sel->get_name()).c_str() : "<none>", p_property.c_str(), p_bit, p_x, p_y));
				}
			};

			// Upload the font atlas in a first (blank) frame: ImGui needs it before NewFrame().
			bool fonts_uploaded = false, fonts_pending = false, ready = false;
			for (int attempt = 0; attempt < 10 && !fonts_uploaded; attempt++) {
				VkCommandBuffer cb = swap_chain.begin_frame(Color(0.1f, 0.1f, 0.12f, 1.0f));
				if (cb) {
					fonts_uploaded = ImGui_ImplVulkan_CreateFontsTexture(cb);
					fonts_pending = true;
					swap_chain.end_frame();
				}
			}
			if (!fonts_uploaded) {
				fprintf(stderr, "godot-area editor: could not upload the UI font.\n");
				s.quit = true;
				code = 1;
			}
			bool layout_logged = false;
			bool log_cells_next = false; // Log the layer-grid cells in the next frame (after ready / resize).
			while (!display.should_close() && !s.quit) {
				// Idle: wait for input instead of spinning (the window only changes on events).
				if (ready && input_queue.empty() && s.pending_screenshot.empty()) {
					glfwWaitEventsTimeout(0.25);
				} else {
					display.poll_events();
				}
				// A resized window: new swapchain images, new panel rectangles, the viewport rendered
				// again at its new size (after the last frame, which samples its old texture, finished).
				int fb_w = 0, fb_h = 0;
				display.get_framebuffer_size(fb_w, fb_h);
				if (fb_w > 0 && fb_h > 0 && (fb_w != swap_chain.get_width() || fb_h != swap_chain.get_height() || !swap_chain.is_valid())) {
					swap_chain.resize(fb_w, fb_h);
				}
				if (fb_w > 0 && fb_h > 0) {
					EditorNode::Layout layout = EditorNode::compute_layout(fb_w, fb_h);
					if (layout.viewport.width != s.layout.viewport.width || layout.viewport.height != s.layout.viewport.height || layout.viewport.x != s.layout.viewport.x || layout.inspector.width != s.layout.inspector.width) {
						swap_chain.wait_frame();
						s.layout = layout;
						s.viewport.set_size(layout.viewport.width, layout.viewport.height);
						layout_logged = false;
					}
				}
				std::vector<InputEvent> events;
				events.swap(input_queue);
				ImGui_ImplVulkan_NewFrame();
				ImGui_ImplGlfw_NewFrame();
				ImGui::NewFrame();
				for (const InputEvent &e : events) {
					if (e.type == InputEvent::KEY) {
						s.handle_key(e);
					} else {
						s.handle_mouse(e);
					}
				}
				s.sync_selection();
				if (s.undo_redo.get_version() != s.seen_undo_version || s.dock.get_version() != s.seen_dock_version) {
					s.seen_undo_version = s.undo_redo.get_version();
					s.seen_dock_version = s.dock.get_version();
					s.viewport.mark_scene_changed();
				}
				s.log_layer_cells = log_cells_next;
				log_cells_next = false;
				s.preview_property.clear();
				s.draw_panels();
				s.log_layer_cells = false;
				s.sync_selection();
				swap_chain.wait_frame(); // The last frame sampled the textures update() may rewrite.
				s.viewport.update();
				s.preview.update(RenderingDevice::get_singleton());
				ImGui::Render();
				VkCommandBuffer cb = swap_chain.begin_frame(Color(0.1f, 0.1f, 0.12f, 1.0f));
				if (fonts_pending) {
					ImGui_ImplVulkan_DestroyFontUploadObjects(); // The upload frame has finished.
					fonts_pending = false;
				}
				if (!cb) {
					continue;
				}
				const bool have_viewport = s.blit.begin_frame(cb, swap_chain.get_width(), swap_chain.get_height(), RenderingDevice::get_singleton(), s.viewport.get_scene_texture(), s.viewport.get_overlay_texture(), s.viewport.get_tonemap());
				const uint64_t blits_before = s.blit.get_draw_count();
				const bool have_preview = s.preview.begin_frame(cb, swap_chain.get_width(), swap_chain.get_height(), RenderingDevice::get_singleton());
				const uint64_t previews_before = s.preview.get_draw_count();
				swap_chain.begin_render_pass();
				ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cb);
				if (have_preview && s.preview.get_draw_count() > previews_before) {
					const float *r = s.preview.get_rect();
					const String where = vformat("%s %d %d %.0f %.0f %s", s.preview_property.c_str(), s.preview.get_width(), s.preview.get_height(), r[0], r[1], s.preview.is_fully_visible() ? "visible" : "clipped");
					if (where != s.preview_logged) {
						s.preview_logged = where;
						s.log_line("preview " + where);
					}
				}
				const bool viewport_drawn = have_viewport && s.blit.get_draw_count() > blits_before;
				bool window_shot = (!p_options.window_screenshot.empty() && ready && !s.window_captured) || s.window_capture_requested;
				const bool viewport_shot = !s.pending_screenshot.empty() && viewport_drawn;
				const String window_path = p_options.window_screenshot.empty() ? String("editor_window.png") : p_options.window_screenshot;
				bool capture = window_shot || viewport_shot;
				if (capture) {
					capture = swap_chain.capture_next_frame();
				}
				swap_chain.end_frame();
				if (viewport_shot) {
					s.write_screenshot(capture ? swap_chain.get_capture() : std::vector<uint8_t>(), swap_chain.get_width(), swap_chain.get_height());
				}
				if (window_shot) {
					s.window_captured = true;
					s.window_capture_requested = false;
				}
				if (window_shot && capture && !swap_chain.get_capture().empty()) {
					String err;
					if (PNGWriter::save_rgba8(swap_chain.get_capture(), swap_chain.get_width(), swap_chain.get_height(), window_path, &err)) {
						s.status_message = "Wrote " + window_path;
						s.log_line("window_screenshot " + window_path);
					} else {
						s.log_line("window_screenshot error " + err);
					}
				}
				const EditorNode::Rect &v = s.layout.viewport;
				if (!ready && viewport_drawn) {
					// A frame presented with the rendered viewport: the layout has settled.
					ready = s.viewport.get_frames_rendered() > 0 && fonts_uploaded && !fonts_pending;
					if (ready) {
						s.log_line(vformat("ready viewport %d %d %d %d window %d %d", v.x, v.y, v.width, v.height, swap_chain.get_width(), swap_chain.get_height()));
						s.log_handles();
						layout_logged = true;
						log_cells_next = true;
					}
				} else if (ready && !layout_logged && viewport_drawn && s.viewport.get_width() == v.width && s.viewport.get_height() == v.height) {
					// Presented at the new size: where everything is now.
					layout_logged = true;
					s.log_line(vformat("resize window %d %d viewport %d %d %d %d", swap_chain.get_width(), swap_chain.get_height(), v.x, v.y, v.width, v.height));
					s.log_handles();
					log_cells_next = true;
				}
			}
			swap_chain.wait_idle();
			EditorProperties::layer_cell_callback = nullptr;
			EditorProperties::resource_preview_callback = nullptr;
			EditorProperties::resource_load_callback = nullptr;
			s.preview.destroy(RenderingDevice::get_singleton());
			s.blit.destroy();
			ImGui_ImplVulkan_Shutdown();
			ImGui_ImplGlfw_Shutdown();
			ImGui::DestroyContext();
		}
		s.viewport.clear();
		swap_chain.destroy();
		if (pool) {
			vkDestroyDescriptorPool((VkDevice)vk.device, pool, nullptr);
		}
		s.dock.set_edited_scene(nullptr);
		s.inspector.edit(nullptr);
		s.undo_redo.clear_history(); // Frees nodes that only the history held.
		if (s.scene && !s.scene->get_parent()) {
			delete s.scene; // Never added to the tree; otherwise the tree deletes it.
		}
		s.scene = nullptr;
	}
	int validation_errors = engine.get_validation_error_count();
	if (validation_errors > 0) {
		fprintf(stderr, "godot-area: the Vulkan validation layer reported %d error(s) (see above)\n", validation_errors);
		code = code ? code : 1;
	}
	uninitialize_modules();
	engine.stop();
	display.finalize();
	s.log_line(vformat("exit %d validation_errors %d", code, validation_errors));
	if (s.log) {
		fclose(s.log);
	}
	return code;
}

#endif // GODOT_AREA_EDITOR_WINDOW
