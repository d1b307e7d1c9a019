/**************************************************************************/
/*  demo_renders.h                                                        */
/**************************************************************************/
/* godot-area: what `render --compare-punctual` and `render --frames N    */
/* --path SPEC` change in a loaded scene (main/main.cpp runs them).        */
/*                                                                        */
/* Punctual stand-ins. An AreaLight3D of colour c and energy E (area A,   */
/* area_normalize_energy on) emits radiance L = c E pi / A from one side  */
/* (scene/3d/light_3d.h), so its radiant intensity at angle t from its    */
/* normal is I(t) = L A cos t = c E pi cos t and its power               */
/* P = integral of I over the hemisphere = c E pi^2. A SpotLight3D has    */
/* I(t) = c E' pi * cone(t) (Godot 4 without physical light units; the    */
/* renderer multiplies energy by pi), with                                */
/* cone(t) = 1 - ((1 - cos t) / (1 - cos a))^k, a = spot_angle,           */
/* k = spot_angle_attenuation. With a = 90 degrees and k = 1 that is      */
/* cos t: the spot has the area light's exact far-field distribution, and */
/* equal power (c E' pi^2) means E' = E. Generally                        */
/*   P_spot = c E' pi * 2 pi (1 - cos a) k / (k + 1),                      */
/* and an OmniLight3D has P = 4 pi^2 c E' (so E' = E / 4). Without         */
/* area_normalize_energy, L = c E pi and every E above gains the factor A. */
/* The distance falloff is kept: spot_attenuation = area_attenuation      */
/* (2 = inverse square for both), spot_range = area_range.                */

#pragma once

#include "core/math/transform_3d.h"
#include "core/string/ustring.h"

#include <vector>

class Node;

namespace DemoRenders {

// Replaces every AreaLight3D under p_root (recursively) by a SpotLight3D of equal power and the same
// colour, transform, range, falloff, specular and cull mask (spot_angle 90, spot_angle_attenuation 1;
// see above). The spot has no shadow (this renderer draws no omni/spot shadows). One line per light in
// r_report (name, area energy, spot energy). Returns the number replaced.
int replace_area_lights_with_spots(Node *p_root, std::vector<String> *r_report = nullptr);

// The spot energy of equal power for an area light (see above); also used by the tests.
float spot_energy_for_area_light(float p_area_energy, float p_area_width, float p_area_height, bool p_normalize_energy, float p_spot_angle_degrees = 90.0f, float p_spot_angle_attenuation = 1.0f);

// A camera path for `render --frames N --path SPEC`:
//   orbit:DEGREES@X,Y,Z   turns the camera about the vertical axis through (X, Y, Z), from -DEGREES/2 to
//                         +DEGREES/2 (the camera keeps looking the same way relative to the pivot);
//   dolly:DX,DY,DZ        moves the camera from its position to position + (DX, DY, DZ) (world metres).
struct CameraPath {
	enum Kind {
		ORBIT,
		DOLLY,
	};
	Kind kind = ORBIT;
	float degrees = 0.0f;
	Vector3 pivot;
	Vector3 offset;

	// The camera's global transform at p_t in [0, 1] along the path, starting from p_start.
	Transform3D sample(const Transform3D &p_start, float p_t) const;
};

// False with r_error naming the spec and what is wrong.
bool parse_camera_path(const String &p_spec, CameraPath &r_path, String *r_error);

// Godot's Movie Maker numbering: "out/frame.exr", 3 -> "out/frame00000003.exr".
String numbered_path(const String &p_path, int p_frame);

// "out/demo.png", "_punctual" -> "out/demo_punctual.png".
String suffixed_path(const String &p_path, const String &p_suffix);

} // namespace DemoRenders
