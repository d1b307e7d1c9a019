/**************************************************************************/
/*  sky.glsl                                                              */
/**************************************************************************/
/* Sky background of the Forward+ renderer (SkyRD, effects/sky_rd.h): a   */
/* fullscreen triangle at the far plane, drawn after the opaque pass with */
/* depth test LESS_OR_EQUAL, so it covers exactly the pixels no geometry  */
/* wrote. Each pixel evaluates the ProceduralSkyMaterial formula along    */
/* its world-space view ray; the C++ twin (and the formula) is            */
/* servers/rendering/sky_model.h, which the SH ambient and the Embree      */
/* reference use. Output: linear HDR radiance.                            */

#[vertex]

#version 450

void main() {
	// Fullscreen triangle: (-1,-1), (3,-1), (-1,3) at depth 1 (the far plane of the Vulkan depth range).
	vec2 p = vec2(float((gl_VertexIndex << 1) & 2), float(gl_VertexIndex & 2)) * 2.0 - 1.0;
	gl_Position = vec4(p, 1.0, 1.0);
}

#[fragment]

#version 450

layout(set = 0, binding = 0, std140) uniform SkyDataBlock { // Mirror: SkyRD::SkyDataUBO.
	mat4 view_from_clip; // Inverse of the depth-corrected projection.
	mat4 world_from_view;
	vec4 viewport_size; // xy pixels.
	vec4 sky_top; // rgb linear * energies.
	vec4 sky_horizon;
	vec4 ground_bottom;
	vec4 ground_horizon;
	vec4 curves; // sky_curve, ground_curve, sun_angle_max (rad), sun_curve.
	vec4 sun_direction; // xyz world, towards the sun; w = size (rad).
	vec4 sun_radiance; // rgb; w = 1 when the sun is drawn.
}
sky;

layout(location = 0) out vec4 frag_color;

float sky_curve_blend(float p_c, float p_curve) {
	float base = clamp(1.0 - p_c, 0.0, 1.0);
	float t = p_curve > 0.0 ? 1.0 - pow(base, 1.0 / p_curve) : (base < 1.0 ? 1.0 : 0.0);
	return clamp(t, 0.0, 1.0);
}

vec3 sky_evaluate(vec3 p_dir) {
	const float half_pi = 1.57079632679;
	float v = acos(clamp(p_dir.y, -1.0, 1.0));
	if (p_dir.y >= 0.0) {
		vec3 c = mix(sky.sky_horizon.rgb, sky.sky_top.rgb, sky_curve_blend(1.0 - v / half_pi, sky.curves.x));
		if (sky.sun_radiance.w > 0.0) {
			float s = acos(clamp(dot(sky.sun_direction.xyz, p_dir), -1.0, 1.0));
			float size = sky.sun_direction.w;
			if (s < size) {
				c = sky.sun_radiance.rgb;
			} else if (s < sky.curves.z) {
				float c2 = (s - size) / max(sky.curves.z - size, 1e-6);
				c = mix(sky.sun_radiance.rgb, c, sky_curve_blend(c2, sky.curves.w));
			}
		}
		return c;
	}
	return mix(sky.ground_horizon.rgb, sky.ground_bottom.rgb, sky_curve_blend((v - half_pi) / half_pi, sky.curves.y));
}

void main() {
	vec2 ndc = gl_FragCoord.xy / sky.viewport_size.xy * 2.0 - 1.0;
	vec4 far_view = sky.view_from_clip * vec4(ndc, 1.0, 1.0);
	vec4 near_view = sky.view_from_clip * vec4(ndc, 0.0, 1.0);
	vec3 view_dir = far_view.xyz / far_view.w - near_view.xyz / near_view.w;
	vec3 dir = normalize(mat3(sky.world_from_view) * view_dir);
	frag_color = vec4(sky_evaluate(dir), 1.0);
}
