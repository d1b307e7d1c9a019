/**************************************************************************/
/*  test_area_shadow_near_layer.cpp                                       */
/**************************************************************************/
/* Which grid lights get the near-layer step of the area shadow lookup:   */
/* only those with a caster within the layer's reach of their sample      */
/* points (AreaShadowRendererRD::caster_in_near_layer), so a view whose   */
/* casters are all far pays nothing for it on llvmpipe.                   */

#include "servers/rendering/renderer_rd/effects/area_shadow_renderer.h"

#include <doctest/doctest.h>

#include <cmath>

namespace TestAreaShadowNearLayer {

TEST_CASE("[AreaLight3D][Shadows] the near-layer step is compiled in only for a light with a caster close to it") {
	// A 1 m light 2.5 m above the floor facing down (range 6: farthest receiver 6 + sqrt(2) m from a sample
	// point), as bench --targets' S1/S2 scene: the near layer reaches 1.25 x 7.41 / 9 = 1.03 m from it.
	const Transform3D world_from_light(Basis::from_axis_angle(Vector3(1, 0, 0), -float(Math::PI) * 0.5f), Vector3(0, 2.5f, 0));
	const Vector3 half_extent(0.5f, 0.5f, 0.0f);
	const float reach = 6.0f + std::sqrt(2.0f);
	CHECK(AreaShadowRendererRD::near_layer_reach(reach) == doctest::Approx(1.25f * reach / 9.0f));
	// The 1 m box on the floor (its top 1.5 m under the light) and the floor: no near layer.
	CHECK_FALSE(AreaShadowRendererRD::caster_in_near_layer(world_from_light, half_extent, reach, AABB(Vector3(-0.5f, 0, -0.5f), Vector3(1, 1, 1))));
	CHECK_FALSE(AreaShadowRendererRD::caster_in_near_layer(world_from_light, half_extent, reach, AABB(Vector3(-12, 0, -12), Vector3(24, 0, 24))));
	// A bar 4 cm under the light (a window's mullion) and a box 0.9 m beside the light's edge: near.
	CHECK(AreaShadowRendererRD::caster_in_near_layer(world_from_light, half_extent, reach, AABB(Vector3(-1, 2.41f, -0.025f), Vector3(2, 0.05f, 0.05f))));
	CHECK(AreaShadowRendererRD::caster_in_near_layer(world_from_light, half_extent, reach, AABB(Vector3(1.4f, 2.0f, -0.5f), Vector3(0.5f, 0.5f, 1))));
	// The same box 1.1 m beside it: not near.
	CHECK_FALSE(AreaShadowRendererRD::caster_in_near_layer(world_from_light, half_extent, reach, AABB(Vector3(1.6f, 2.0f, -0.5f), Vector3(0.5f, 0.5f, 1))));
}

} // namespace TestAreaShadowNearLayer
