/**************************************************************************/
/*  area_light_shapes.h                                                   */
/**************************************************************************/
/* godot-area: the reference renderer's estimator of one disk, sphere or  */
/* tube area light at one surface point (the rectangle's is               */
/* area_light_integrate()), with the contract's units (area_light.h):     */
/*   L_o = W(d) * integral over the shape of f(l, v) L_e (n.l) dw,        */
/* the shape as real geometry with exact emission: the disk one-sided     */
/* (its emitting side only), the sphere and the capsule outwards from     */
/* every point of their surface (a direction counts when its ray's FIRST  */
/* hit is the shape). Multiple importance sampling (Veach 1997, power     */
/* heuristic, one sample per strategy and evaluation) of                  */
/*  (1) light samples: the sphere uniform in its cone of directions       */
/*      (Shirley and Wang 1992; pbrt-v4 Sphere::Sample), the disk and the */
/*      capsule uniform over their area (pdf_w = d^2 / (A cos theta_l)),  */
/*  (2) BRDF samples: cosine-weighted directions mixed with GGX visible   */
/*      normals (Heitz 2018), as area_light_integrate(), with an exact    */
/*      ray / shape intersection;                                          */
/* every sample weighted by the C++ twin BRDF (light_compute), shadowed   */
/* by the occlusion callback towards the point on the shape.              */

#pragma once

#include "modules/reference/area_light_integrator.h"

namespace ReferenceBRDF {

// p_light.shape must not be AREA_LIGHT_SHAPE_RECTANGLE (that is area_light_integrate()).
AreaLightIntegral area_light_shape_integrate(const AreaLightData &p_light, const AreaLightShadingPoint &p_point, const AdaptiveIntegrationSettings &p_settings, ReferenceRNG &r_rng, const AreaLightOcclusionTest &p_occluded = AreaLightOcclusionTest());

// First hit (distance along the unit p_dir from p_origin, and the outward unit normal there) of the
// ray with the shape; false when it misses (the disk only from its emitting side).
bool area_light_shape_intersect(const AreaLightData &p_light, const Vector3 &p_origin, const Vector3 &p_dir, float &r_t, Vector3 &r_normal);

} // namespace ReferenceBRDF
