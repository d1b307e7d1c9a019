/**************************************************************************/
/*  scene_tree_editor.cpp                                                 */
/**************************************************************************/
/* godot-area: see scene_tree_editor.h.                                   */

#include "editor/scene_tree_editor.h"

#ifdef GODOT_AREA_EDITOR_WINDOW

#include "editor/editor_icons.h"
#include "editor/editor_inspector.h"
#include "editor/scene_tree_dock.h"
#include "scene/main/missing_node.h"
#include "scene/main/node.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <vector>

void SceneTreeEditor::draw_icon(const String &p_name, float p_x, float p_y, float p_size, float p_alpha) {
	const EditorIcon *icon = EditorIcons::get_icon(p_name);
	if (!icon) {
		return;
	}
	ImDrawList *dl = ImGui::GetWindowDrawList();
	const float s = p_size / std::max(icon->view_size.x, icon->view_size.y);
	auto col = [p_alpha](const Color &p_c) { return ImGui::GetColorU32(ImVec4(p_c.r, p_c.g, p_c.b, p_c.a * p_alpha)); };
	auto pt = [&](const Vector2 &p_v) { return ImVec2(p_x + p_v.x * s, p_y + p_v.y * s); };
	for (const EditorIconShape &shape : icon->shapes) {
		switch (shape.type) {
			case EditorIconShape::RECT: {
				ImVec2 a = pt(shape.position), b = pt(shape.position + shape.size);
				if (shape.has_fill) {
					dl->AddRectFilled(a, b, col(shape.fill), shape.radius * s);
				}
				if (shape.has_stroke) {
					dl->AddRect(a, b, col(shape.stroke), shape.radius * s, 0, shape.stroke_width * s);
				}
			} break;
			case EditorIconShape::CIRCLE: {
				if (shape.has_fill) {
					dl->AddCircleFilled(pt(shape.position), shape.radius * s, col(shape.fill), 24);
				}
				if (shape.has_stroke) {
					dl->AddCircle(pt(shape.position), shape.radius * s, col(shape.stroke), 24, shape.stroke_width * s);
				}
			} break;
			case EditorIconShape::POLYGON: {
				std::vector<ImVec2> points;
				for (const Vector2 &p : shape.points) {
					points.push_back(pt(p));
				}
				if (shape.has_fill) {
					dl->AddConvexPolyFilled(points.data(), (int)points.size(), col(shape.fill));
				}
				if (shape.has_stroke) {
					dl->AddPolyline(points.data(), (int)points.size(), col(shape.stroke), ImDrawFlags_Closed, shape.stroke_width * s);
				}
			} break;
		}
	}
}

void SceneTreeEditor::_draw_node(Node *p_node) {
	ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_OpenOnArrow | ImGuiTreeNodeFlags_DefaultOpen | ImGuiTreeNodeFlags_SpanAvailWidth;
	if (p_node->get_child_count() == 0) {
		flags |= ImGuiTreeNodeFlags_Leaf;
	}
	if (dock->get_selected() == p_node) {
		flags |= ImGuiTreeNodeFlags_Selected;
	}
	// As Godot's scene dock: the class icon (nearest ancestor's when the class has none), then the
	// name; the class is in the tooltip. A MissingNode is a dimmed placeholder with a warning.
	const float icon_size = ImGui::GetTextLineHeight() + 2;
	const float space = std::max(1.0f, ImGui::CalcTextSize(" ").x);
	const String pad((size_t)std::ceil((icon_size + 4) / space), ' ');
	const MissingNode *missing = Object::cast_to<MissingNode>(p_node);
	if (missing) {
		ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
	}
	bool open = ImGui::TreeNodeEx((void *)p_node, flags, "%s%s", pad.c_str(), String(p_node->get_name()).c_str());
	if (missing) {
		ImGui::PopStyleColor();
	}
	const ImVec2 item_min = ImGui::GetItemRectMin(), item_max = ImGui::GetItemRectMax();
	const float icon_y = item_min.y + (item_max.y - item_min.y - icon_size) * 0.5f;
	draw_icon(EditorIcons::get_object_icon_name(p_node), item_min.x + ImGui::GetTreeNodeToLabelSpacing(), icon_y, icon_size, missing ? 0.75f : 1.0f);
	if (missing) {
		draw_icon("NodeWarning", item_max.x - icon_size - 2, icon_y, icon_size);
	}
	if (ImGui::IsItemHovered()) {
		if (missing) {
			ImGui::SetTooltip("%s\nType: MissingNode (placeholder for '%s')\nThis node was saved as class '%s', which this engine does not have.\nIts properties are kept as they were and are written back on save.", String(p_node->get_name()).c_str(), missing->get_original_class().c_str(), missing->get_original_class().c_str());
		} else {
			ImGui::SetTooltip("%s\nType: %s", String(p_node->get_name()).c_str(), p_node->get_class().c_str());
		}
	}
	if (ImGui::IsItemClicked() && !ImGui::IsItemToggledOpen()) {
		dock->select(p_node);
	}
	if (p_node != dock->get_edited_scene() && ImGui::BeginDragDropSource()) {
		ImGui::SetDragDropPayload("GODOT_AREA_NODE", &p_node, sizeof(Node *));
		ImGui::Text("Move %s", p_node->get_name().c_str());
		ImGui::EndDragDropSource();
	}
	if (ImGui::BeginDragDropTarget()) {
		if (const ImGuiPayload *payload = ImGui::AcceptDragDropPayload("GODOT_AREA_NODE")) {
			pending_move = *(Node *const *)payload->Data;
			pending_parent = p_node;
		}
		ImGui::EndDragDropTarget();
	}
	if (open) {
		for (int i = 0; i < p_node->get_child_count(); i++) {
			_draw_node(p_node->get_child(i));
		}
		ImGui::TreePop();
	}
}

void SceneTreeEditor::draw() {
	if (!dock || !dock->get_edited_scene()) {
		ImGui::TextDisabled("No scene.");
		return;
	}
	ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - 60);
	bool add = ImGui::InputTextWithHint("##class", "Class name", &add_class, ImGuiInputTextFlags_EnterReturnsTrue);
	ImGui::SameLine();
	add = ImGui::Button("Add", ImVec2(-1, 0)) || add;
	if (add) {
		Node *parent = dock->get_selected() ? dock->get_selected() : dock->get_edited_scene();
		last_error = dock->add_node(String(add_class), parent) ? String() : "cannot add a node of class '" + String(add_class) + "'";
	}
	Node *selected = dock->get_selected();
	bool can_delete = selected && selected != dock->get_edited_scene();
	if (!can_delete) {
		ImGui::BeginDisabled();
	}
	if (ImGui::Button("Delete")) {
		last_error = dock->delete_node(selected) ? String() : "cannot delete " + selected->get_name();
	}
	if (!can_delete) {
		ImGui::EndDisabled();
	}
	ImGui::SameLine();
	const String hint = "drag a node onto another to reparent";
	const String fitted = EditorInspector::fit_text(hint, ImGui::GetContentRegionAvail().x, [](const String &p_text) { return ImGui::CalcTextSize(p_text.c_str()).x; });
	ImGui::TextDisabled("%s", fitted.c_str());
	if (fitted != hint && ImGui::IsItemHovered()) {
		ImGui::SetTooltip("%s", hint.c_str());
	}
	if (!last_error.empty()) {
		ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", last_error.c_str());
	}
	ImGui::Separator();
	ImGui::BeginChild("tree");
	_draw_node(dock->get_edited_scene());
	ImGui::EndChild();
	// Reparent after drawing: the tree must not change while it is walked.
	if (pending_move && pending_parent) {
		if (!dock->reparent_node(pending_move, pending_parent)) {
			last_error = "cannot move " + pending_move->get_name() + " under " + pending_parent->get_name();
		} else {
			last_error = String();
		}
	}
	pending_move = nullptr;
	pending_parent = nullptr;
}

#else

// Without the window build there is no ImGui: nothing is drawn.
void SceneTreeEditor::draw_icon(const String &p_name, float p_x, float p_y, float p_size, float p_alpha) {}
void SceneTreeEditor::_draw_node(Node *p_node) {}
void SceneTreeEditor::draw() {}

#endif
