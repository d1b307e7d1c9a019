/**************************************************************************/
/*  editor_properties.cpp                                                 */
/**************************************************************************/
/* godot-area: see editor_properties.h.                                   */

#include "editor/editor_properties.h"

#ifdef GODOT_AREA_EDITOR_WINDOW

#include "core/math/color.h"
#include "core/math/math_funcs.h"
#include "core/math/transform_3d.h"
#include "core/math/vector2.h"
#include "core/math/vector3.h"
#include "editor/editor_inspector.h"
#include "editor/editor_resource_preview.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

std::function<void(const String &, int, float, float)> EditorProperties::layer_cell_callback;
std::function<void(const EditorPropertyRow &, const Variant &)> EditorProperties::resource_preview_callback;
std::function<Variant(const String &, const String &, String *)> EditorProperties::resource_load_callback;

namespace {

// "%.3f m" style display format for a row.
std::string _float_format(const EditorPropertyRow &p_row) {
	int decimals = 3;
	if (p_row.has_range && p_row.range_step > 0) {
		decimals = 0;
		double s = p_row.range_step;
		while (decimals < 6 && std::fabs(s - std::round(s)) > 1e-9) {
			s *= 10;
			decimals++;
		}
	}
	std::string f = "%." + std::to_string(decimals) + "f";
	if (!p_row.suffix.empty()) {
		f += " " + p_row.suffix;
	}
	return f;
}

float _drag_speed(const EditorPropertyRow &p_row) {
	if (p_row.has_range && p_row.range_step > 0) {
		return (float)p_row.range_step;
	}
	return 0.01f;
}

// Drag bounds: the range, opened where or_greater / or_less allow it (0, 0 = unbounded for ImGui).
void _drag_bounds(const EditorPropertyRow &p_row, float &r_min, float &r_max) {
	r_min = 0.0f;
	r_max = 0.0f;
	if (!p_row.has_range) {
		return;
	}
	r_min = p_row.or_less ? -FLT_MAX : (float)p_row.range_min;
	r_max = p_row.or_greater ? FLT_MAX : (float)p_row.range_max;
}

float _measure(const String &p_text) {
	return ImGui::CalcTextSize(p_text.c_str()).x;
}

// The display format for p_count drag fields sharing the item width: the row's format if every
// value fits its field, else without the suffix, else with fewer decimals (the value itself is
// kept; the whole value is in the tooltip). Long values never run past their field.
std::string _fit_float_format(const EditorPropertyRow &p_row, const float *p_values, int p_count) {
	const float spacing = ImGui::GetStyle().ItemInnerSpacing.x;
	const float field = (ImGui::CalcItemWidth() - spacing * (p_count - 1)) / p_count - ImGui::GetStyle().FramePadding.x * 2;
	const std::string full = _float_format(p_row);
	auto fits = [&](const std::string &p_format) {
		char buffer[64];
		for (int i = 0; i < p_count; i++) {
			snprintf(buffer, sizeof(buffer), p_format.c_str(), p_values[i]);
			if (_measure(buffer) > field) {
				return false;
			}
		}
		return true;
	};
	if (fits(full)) {
		return full;
	}
	int decimals = 3;
	size_t dot = full.find('.');
	if (dot != std::string::npos) {
		decimals = atoi(full.c_str() + dot + 1);
	}
	for (int d = decimals; d >= 0; d--) {
		std::string f = "%." + std::to_string(d) + "f";
		if (fits(f)) {
			return f;
		}
	}
	return "%.0f";
}

void _value_tooltip(const EditorPropertyRow &p_row, const float *p_values, int p_count) {
	if (!ImGui::IsItemHovered() || ImGui::IsItemActive()) {
		return;
	}
	String text;
	for (int i = 0; i < p_count; i++) {
		text += (i ? ", " : "") + vformat("%g", p_values[i]);
	}
	ImGui::SetTooltip("%s%s%s", text.c_str(), p_row.suffix.empty() ? "" : " ", p_row.suffix.c_str());
}

// A combo whose preview is fitted to the field (ImGui would cut it mid-letter).
bool _begin_combo(const char *p_id, const String &p_preview) {
	const float room = ImGui::CalcItemWidth() - ImGui::GetFrameHeight() - ImGui::GetStyle().FramePadding.x * 2;
	const String fitted = EditorInspector::fit_text(p_preview, room, _measure);
	const bool open = ImGui::BeginCombo(p_id, fitted.c_str());
	if (fitted != p_preview && ImGui::IsItemHovered()) {
		ImGui::SetTooltip("%s", p_preview.c_str());
	}
	return open;
}

void _track(EditorProperties::Result &r_result, bool p_changed) {
	r_result.changed = r_result.changed || p_changed;
	r_result.active = r_result.active || ImGui::IsItemActive();
	r_result.deactivated = r_result.deactivated || ImGui::IsItemDeactivated();
}

} // namespace

float EditorProperties::measure_label(const EditorPropertyRow &p_row) {
	return _measure(p_row.label);
}

EditorProperties::Result EditorProperties::draw_row(const EditorPropertyRow &p_row, const Variant &p_value, Variant &r_value, float p_label_width) {
	Result result;
	ImGui::PushID(p_row.property.c_str());
	ImGui::AlignTextToFramePadding();
	// The label never runs into the value: fitted to its column, with an ellipsis when cut.
	const float label_x = ImGui::GetCursorPosX();
	const float spacing = ImGui::GetStyle().ItemSpacing.x;
	const String label = EditorInspector::fit_text(p_row.label, p_label_width - spacing, _measure);
	ImGui::TextUnformatted(label.c_str());
	if (ImGui::IsItemHovered()) {
		ImGui::SetTooltip("%s\n%s (%s)", p_row.label.c_str(), p_row.property.c_str(), Variant::get_type_name(p_row.type).c_str());
	}
	ImGui::SameLine(label_x + p_label_width);
	ImGui::SetNextItemWidth(-1);
	if (p_row.read_only) {
		ImGui::BeginDisabled();
	}
	// "radians_as_degrees" (or "radians"): stored in radians, shown and ranged in degrees.
	const float scale = p_row.hint == PROPERTY_HINT_RANGE && p_row.hint_string.find("radians") != String::npos ? (float)(180.0 / Math::PI) : 1.0f;
	const bool is_enum = (p_row.hint == PROPERTY_HINT_ENUM || p_row.hint == PROPERTY_HINT_ENUM_SUGGESTION) && !p_row.enum_options.empty();
	switch (p_row.type) {
		case Variant::BOOL: {
			bool v = p_value.to_bool();
			_track(result, ImGui::Checkbox("##v", &v));
			r_value = v;
		} break;
		case Variant::INT: {
			int64_t current = p_value.to_int();
			if (is_enum) {
				int index = -1;
				for (size_t i = 0; i < p_row.enum_values.size(); i++) {
					if (p_row.enum_values[i] == current) {
						index = (int)i;
					}
				}
				const String preview = index >= 0 ? p_row.enum_options[index] : vformat("%lld (not an option)", (long long)current);
				if (_begin_combo("##v", preview)) {
					for (size_t i = 0; i < p_row.enum_options.size(); i++) {
						if (ImGui::Selectable(p_row.enum_options[i].c_str(), (int)i == index)) {
							r_value = (int64_t)p_row.enum_values[i];
							result.changed = p_row.enum_values[i] != current;
						}
					}
					ImGui::EndCombo();
				}
			} else if (EditorInspector::get_layer_count(p_row.hint) > 0) {
				// Godot's layer grid: numbered toggles in two rows, the mask as unsigned hex beside.
				const int layers = EditorInspector::get_layer_count(p_row.hint);
				const uint32_t mask = EditorInspector::get_layer_mask(p_value);
				// Cells shrink with the field (four rows when two would be too narrow).
				int rows = 2;
				const float cell = EditorInspector::get_layer_cell_size(layers, ImGui::GetContentRegionAvail().x, 2.0f, ImGui::GetFrameHeight() * 0.95f, ImGui::CalcTextSize("20").x + 4.0f, rows);
				const float grid_x = ImGui::GetCursorPosX();
				ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(2, 2));
				ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(1, 1));
				for (int bit = 0; bit < layers; bit++) {
					if (bit % (layers / rows) != 0) {
						ImGui::SameLine();
					} else if (bit > 0) {
						ImGui::SetCursorPosX(grid_x);
					}
					const bool on = (mask >> bit) & 1u;
					ImGui::PushStyleColor(ImGuiCol_Button, on ? ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive) : ImGui::GetStyleColorVec4(ImGuiCol_FrameBg));
					const std::string id = std::to_string(bit + 1) + "##layer" + std::to_string(bit);
					if (ImGui::Button(id.c_str(), ImVec2(cell, cell))) {
						r_value = EditorInspector::toggle_layer(p_value, bit);
						result.changed = true;
					}
					if (ImGui::IsItemHovered()) {
						ImGui::SetTooltip("Layer %d (bit %d) %s", bit + 1, bit, on ? "on" : "off");
					}
					if (layer_cell_callback) {
						const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
						layer_cell_callback(p_row.property, bit, (a.x + b.x) * 0.5f, (a.y + b.y) * 0.5f);
					}
					ImGui::PopStyleColor();
				}
				ImGui::PopStyleVar(2);
				ImGui::SetCursorPosX(grid_x);
				ImGui::TextDisabled("0x%08X", mask);
			} else if (p_row.hint == PROPERTY_HINT_FLAGS && !p_row.enum_options.empty()) {
				int64_t flags = current;
				for (size_t i = 0; i < p_row.enum_options.size(); i++) {
					bool on = (flags & p_row.enum_values[i]) != 0;
					if (ImGui::Checkbox(p_row.enum_options[i].c_str(), &on)) {
						flags = on ? (flags | p_row.enum_values[i]) : (flags & ~p_row.enum_values[i]);
						result.changed = true;
					}
				}
				r_value = flags;
			} else {
				int v = (int)current;
				if (p_row.has_range && !p_row.or_greater && !p_row.or_less) {
					_track(result, ImGui::SliderInt("##v", &v, (int)p_row.range_min, (int)p_row.range_max));
				} else {
					float lo, hi;
					_drag_bounds(p_row, lo, hi);
					_track(result, ImGui::DragInt("##v", &v, 0.2f, lo <= -FLT_MAX ? INT32_MIN : (int)lo, hi >= FLT_MAX ? INT32_MAX : (int)hi));
				}
				r_value = (int64_t)v;
			}
		} break;
		case Variant::FLOAT: {
			float v = (float)p_value.to_float() * scale;
			std::string fmt = _fit_float_format(p_row, &v, 1);
			ImGuiSliderFlags flags = p_row.exp ? ImGuiSliderFlags_Logarithmic : 0;
			if (p_row.has_range && !p_row.or_greater && !p_row.or_less) {
				_track(result, ImGui::SliderFloat("##v", &v, (float)p_row.range_min, (float)p_row.range_max, fmt.c_str(), flags));
			} else {
				float lo, hi;
				_drag_bounds(p_row, lo, hi);
				_track(result, ImGui::DragFloat("##v", &v, _drag_speed(p_row), lo, hi, fmt.c_str(), flags));
			}
			r_value = (double)(v / scale);
		} break;
		case Variant::STRING: {
			std::string s = p_value.to_string();
			if (is_enum) {
				if (_begin_combo("##v", s)) {
					for (const String &option : p_row.enum_options) {
						if (ImGui::Selectable(option.c_str(), option == s)) {
							r_value = option;
							result.changed = option != s;
						}
					}
					ImGui::EndCombo();
				}
			} else if (ImGui::InputText("##v", &s, ImGuiInputTextFlags_EnterReturnsTrue)) {
				r_value = String(s);
				result.changed = true;
			}
		} break;
		case Variant::VECTOR2: {
			Vector2 v = p_value;
			float f[2] = { (float)v.x * scale, (float)v.y * scale };
			float lo, hi;
			_drag_bounds(p_row, lo, hi);
			_track(result, ImGui::DragFloat2("##v", f, _drag_speed(p_row), lo, hi, _fit_float_format(p_row, f, 2).c_str()));
			_value_tooltip(p_row, f, 2);
			r_value = Vector2(f[0] / scale, f[1] / scale);
		} break;
		case Variant::VECTOR3: {
			Vector3 v = p_value;
			float f[3] = { (float)v.x * scale, (float)v.y * scale, (float)v.z * scale };
			float lo, hi;
			_drag_bounds(p_row, lo, hi);
			_track(result, ImGui::DragFloat3("##v", f, _drag_speed(p_row), lo, hi, _fit_float_format(p_row, f, 3).c_str()));
			_value_tooltip(p_row, f, 3);
			r_value = Vector3(f[0] / scale, f[1] / scale, f[2] / scale);
		} break;
		case Variant::COLOR: {
			Color c = p_value;
			float f[4] = { c.r, c.g, c.b, c.a };
			// Godot's colour property: a swatch that opens the picker; the components beside it,
			// fitted to the field.
			_track(result, ImGui::ColorEdit4("##v", f, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_NoInputs));
			ImGui::SameLine();
			const String components = vformat("%.3g, %.3g, %.3g, %.3g", f[0], f[1], f[2], f[3]);
			ImGui::TextDisabled("%s", EditorInspector::fit_text(components, ImGui::GetContentRegionAvail().x, _measure).c_str());
			r_value = Color(f[0], f[1], f[2], f[3]);
		} break;
		case Variant::TRANSFORM3D: {
			// The origin is edited; the basis is shown (edit rotations with a gizmo or in the file).
			Transform3D t = p_value;
			float f[3] = { (float)t.origin.x, (float)t.origin.y, (float)t.origin.z };
			_track(result, ImGui::DragFloat3("##origin", f, 0.01f, 0.0f, 0.0f, "%.3f m"));
			t.origin = Vector3(f[0], f[1], f[2]);
			r_value = t;
			Vector3 s = t.basis.get_scale();
			ImGui::TextDisabled("scale %.3g %.3g %.3g (basis not editable here)", s.x, s.y, s.z);
		} break;
		case Variant::OBJECT: {
			if (p_row.resource_type.empty()) {
				ImGui::TextDisabled("%s", EditorResourcePreview::describe(p_value).c_str());
				break;
			}
			// Godot's EditorResourcePicker: what the value is (with its preview), a file to load, Clear.
			const String text = EditorResourcePreview::describe(p_value);
			const String fitted = EditorInspector::fit_text(text, ImGui::GetContentRegionAvail().x, _measure);
			ImGui::TextUnformatted(fitted.c_str());
			if (ImGui::IsItemHovered()) {
				ImGui::SetTooltip("%s\n(%s)", text.c_str(), p_row.resource_type.c_str());
			}
			if (resource_preview_callback && p_value.get_object()) {
				ImGui::SetCursorPosX(label_x + p_label_width);
				resource_preview_callback(p_row, p_value);
			}
			static std::map<std::string, std::string> typed_paths; // What the user typed, per property.
			static std::map<std::string, std::string> load_errors;
			std::string &path = typed_paths[p_row.property];
			ImGui::SetCursorPosX(label_x + p_label_width);
			const float buttons = _measure("Load") + _measure("Clear") + ImGui::GetStyle().FramePadding.x * 4 + spacing * 2;
			ImGui::SetNextItemWidth(std::max(40.0f, ImGui::GetContentRegionAvail().x - buttons));
			bool load = ImGui::InputTextWithHint("##path", "res://... or a file", &path, ImGuiInputTextFlags_EnterReturnsTrue);
			ImGui::SameLine();
			load = ImGui::Button("Load") || load;
			if (load && resource_load_callback && !path.empty()) {
				String error;
				Variant loaded = resource_load_callback(path, p_row.resource_type, &error);
				if (loaded.get_object()) {
					r_value = loaded;
					result.changed = true;
					load_errors.erase(p_row.property);
				} else {
					load_errors[p_row.property] = error;
				}
			}
			ImGui::SameLine();
			ImGui::BeginDisabled(!p_value.get_object());
			if (ImGui::Button("Clear")) {
				r_value = Variant();
				result.changed = true;
			}
			ImGui::EndDisabled();
			auto error = load_errors.find(p_row.property);
			if (error != load_errors.end()) {
				ImGui::SetCursorPosX(label_x + p_label_width);
				ImGui::PushTextWrapPos(0.0f);
				ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", error->second.c_str());
				ImGui::PopTextWrapPos();
			}
		} break;
		default: {
			ImGui::TextDisabled("%s", p_value.get_type() == Variant::NIL ? "<null>" : Variant::get_type_name(p_value.get_type()).c_str());
		} break;
	}
	if (p_row.read_only) {
		ImGui::EndDisabled();
		result.changed = false;
	}
	ImGui::PopID();
	return result;
}

#else

float EditorProperties::measure_label(const EditorPropertyRow &p_row) {
	return 0.0f;
}

EditorProperties::Result EditorProperties::draw_row(const EditorPropertyRow &p_row, const Variant &p_value, Variant &r_value, float p_label_width) {
	return Result();
}

#endif
