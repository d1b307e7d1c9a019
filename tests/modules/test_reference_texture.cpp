/**************************************************************************/
/*  test_reference_texture.cpp                                            */
/**************************************************************************/
/* Issue 15: the reference renderer's mip-mapped texture sample          */
/* (modules/reference/reference_texture.h): the trilinear blend of the    */
/* levels at a level of detail, and the ray-plane uv that its ray         */
/* differentials use. (The mip chain itself: tests/scene/                 */
/* test_texture_mipmaps.cpp; this part needs modules/reference, which the */
/* sanitized fuzz build does not compile.)                                */

#include "modules/reference/reference_texture.h"

#include "core/math/color.h"

#include <doctest/doctest.h>

#include <vector>

namespace TestReferenceTexture {

TEST_CASE("[Reference][TextureMipmaps] the reference blends mip levels trilinearly and finds a ray's uv") {
	// Levels of constant value 0, 1, 2 (as data): lambda 1.25 blends levels 1 and 2 by 0.25.
	Image base(4, 4, Color(0, 0, 0, 1));
	std::vector<Image> levels = { Image(2, 2, Color(1, 1, 1, 1)), Image(1, 1, Color(2, 2, 2, 1)) };
	CHECK(reference_sample_texture_lod(base, &levels, Vector2(0.3f, 0.6f), 1.25f, false).r == doctest::Approx(1.25f));
	CHECK(reference_sample_texture_lod(base, &levels, Vector2(0.3f, 0.6f), 7.0f, true).r == doctest::Approx(2.0f));
	CHECK(reference_sample_texture_lod(base, &levels, Vector2(0.3f, 0.6f), -1.0f, false).r == doctest::Approx(0.0f));
	CHECK(reference_sample_texture_lod(base, nullptr, Vector2(0.3f, 0.6f), 3.0f, false).r == doctest::Approx(0.0f));
	// The ray differential: a ray through a unit triangle's plane at (0.25, 0.5) reads uv (0.25, 0.5).
	const Vector3 tri[3] = { Vector3(0, 0, 0), Vector3(1, 0, 0), Vector3(0, 1, 0) };
	const Vector2 uvs[3] = { Vector2(0, 0), Vector2(1, 0), Vector2(0, 1) };
	Vector2 uv;
	REQUIRE(reference_ray_plane_uv(Vector3(0.25f, 0.5f, 2.0f), Vector3(0, 0, -1), tri, uvs, uv));
	CHECK(uv.x == doctest::Approx(0.25f));
	CHECK(uv.y == doctest::Approx(0.5f));
	CHECK_FALSE(reference_ray_plane_uv(Vector3(0, 0, 1), Vector3(1, 0, 0), tri, uvs, uv));
}

} // namespace TestReferenceTexture
