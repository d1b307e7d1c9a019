/**************************************************************************/
/*  scene_tree_editor.cpp                                                 */
/**************************************************************************/
/* godot-area: see scene_tree_editor.h.                                   */

#include "editor/scene_tree_editor.h"

#ifdef GODOT_AREA_EDITOR_WINDOW

#include "editor/scene_tree_dock.h"
#include "scene/main/node.h"

#include <imgui.h>
#include <imgui_stdlib.h>

void SceneTreeEditor::_draw_node(Node *p_node) {
	ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_OpenOnArrow | ImGuiTreeNodeFlags_DefaultOpen | ImGuiTreeNodeFlags_SpanAvailWidth;
	if (p_node->get_child_count() == 0) {
		flags |= ImGuiTreeNodeFlags_Leaf;
	}
	if (dock->get_selected() == p_node) {
		flags |= ImGuiTreeNodeFlags_Selected;
	}
	String label = p_node->get_name() + "  (" + p_node->get_class() + ")";
	bool open = ImGui::TreeNodeEx((void *)p_node, flags, "%s", label.c_str());
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
	ImGui::TextDisabled("drag a node onto another to reparent");
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

void SceneTreeEditor::_draw_node(Node *p_node) {}
void SceneTreeEditor::draw() {}

#endif
