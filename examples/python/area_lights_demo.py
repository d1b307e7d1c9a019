#!/usr/bin/python3
# godot-area: builds a scene from nothing with the Python module `godot_area` (a floor, a box,
# a sphere and two area lights), sweeps one area light across the scene over N frames, renders
# the last frame and plots the per-pass GPU times of every frame with matplotlib.
# Written as a GDScript user would: ga.AreaLight3D(...), node.look_at(), ga.Vector3, enum names.
#
#   scons -Q -j2                       # builds bin/python/godot_area*.so
#   /usr/bin/python3 examples/python/area_lights_demo.py --frames 40 --png doc/results/python_demo_times.png
#
# Without PYTHONPATH the script looks for the module under bin/python*/ of this repository.
import argparse
import glob
import math
import os
import sys
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
try:
	import godot_area as ga
except ImportError:
	candidates = sorted(glob.glob(os.path.join(ROOT, "bin", "python*", "godot_area*.so")), key=os.path.getmtime, reverse=True)
	if not candidates:
		sys.exit("godot_area is not built: run scons (needs python3-pybind11, see misc/scripts/install_deps.sh)")
	sys.path.insert(0, os.path.dirname(candidates[0]))
	import godot_area as ga


def material(albedo, roughness):
	return ga.StandardMaterial3D(albedo_color=ga.Color(*albedo), roughness=roughness)


def mesh_instance(parent, name, mesh, material_, position=ga.Vector3.ZERO):
	return parent.add_child(ga.MeshInstance3D(name=name, mesh=mesh, material_override=material_, position=position))


def build_scene():
	root = ga.Node3D(name="AreaLightsDemo")

	environment = ga.Environment(background_mode=ga.Environment.BG_COLOR, background_color=ga.Color(0.02, 0.02, 0.03))
	root.add_child(ga.WorldEnvironment(environment=environment))

	mesh_instance(root, "Floor", ga.PlaneMesh(size=ga.Vector2(10, 10)), material((0.6, 0.6, 0.62), 0.25))
	mesh_instance(root, "Box", ga.BoxMesh(size=ga.Vector3(0.8, 0.8, 0.8)), material((0.75, 0.35, 0.2), 0.6), ga.Vector3(-0.8, 0.4, 0.0))
	mesh_instance(root, "Ball", ga.SphereMesh(radius=0.45, height=0.9), material((0.85, 0.85, 0.8), 0.15), ga.Vector3(0.9, 0.45, 0.3))

	camera = root.add_child(ga.Camera3D(name="Camera", fov=55.0, position=ga.Vector3(0.0, 2.6, 4.6)))
	camera.look_at(ga.Vector3(0.0, 0.4, 0.0))

	# A ceiling panel, fixed, facing down (its -Z axis); "up" on the screen is the scene's -Z.
	panel = root.add_child(ga.AreaLight3D(name="Panel", area_size=ga.Vector2(2.0, 1.0), area_range=8.0, light_energy=1.5))
	panel.position = ga.Vector3(0.0, 2.8, 0.0)
	panel.look_at(ga.Vector3.ZERO, ga.Vector3.FORWARD)

	# A warm light strip that sweeps across; MRP shading, no shadow.
	root.add_child(ga.AreaLight3D(name="Strip", area_size=ga.Vector2(0.3, 1.2), area_range=6.0, light_color=ga.Color(1.0, 0.7, 0.4),
			light_energy=4.0, area_shading_method=ga.AreaLight3D.AREA_SHADING_MRP))
	return root


def sweep(strip, frame, frames):
	"""Moves the strip on a half circle around the objects, always facing the centre."""
	angle = math.pi * frame / max(frames - 1, 1)
	strip.position = ga.Vector3(2.5 * math.cos(angle), 1.2, 2.5 * math.sin(angle) - 0.5)
	strip.look_at(ga.Vector3(0.0, 0.4, 0.0))


def preview(image, exposure=1.0):
	"""Reinhard tone map and sRGB encoding of a linear HDR RGBA image, for the plot."""
	rgb = np.clip(image[..., :3] * exposure, 0.0, None)
	rgb = rgb / (1.0 + rgb)
	return np.where(rgb <= 0.0031308, 12.92 * rgb, 1.055 * np.power(rgb, 1.0 / 2.4) - 0.055)


def main():
	parser = argparse.ArgumentParser(description="Builds a scene with two area lights from nothing, sweeps one, plots per-pass GPU times.")
	parser.add_argument("--frames", type=int, default=40)
	parser.add_argument("--warmup", type=int, default=1, help="frames drawn first and left out of the plot (the first frame compiles the pipelines)")
	parser.add_argument("--width", type=int, default=256)
	parser.add_argument("--height", type=int, default=144)
	parser.add_argument("--png", default=os.path.join(ROOT, "doc", "results", "python_demo_times.png"))
	parser.add_argument("--exr", help="also write the last frame as an OpenEXR file")
	parser.add_argument("--save-scene", help="also write the built scene as a .tscn file")
	args = parser.parse_args()
	if args.frames < 1 or args.width < 1 or args.height < 1:
		parser.error("--frames, --width and --height must be at least 1")

	import matplotlib

	matplotlib.use("Agg")
	import matplotlib.pyplot as plt

	ga.init("rd")
	scene = ga.get_tree().root.add_child(build_scene())
	strip = scene.get_node("Strip")
	assert isinstance(strip, ga.AreaLight3D)
	if args.save_scene:
		ga.save_scene(scene, args.save_scene)

	if args.warmup > 0:
		ga.run_frames(args.warmup, lambda frame, tree: sweep(strip, 0, args.frames), args.width, args.height)
	start = time.time()
	profiles = ga.run_frames(args.frames, lambda frame, tree: sweep(strip, frame, args.frames), args.width, args.height)
	elapsed = time.time() - start
	last = ga.render()  # One more frame (the strip stays at its last position), read back.
	if args.exr:
		ga.save_exr(last, args.exr)

	passes = list(profiles[0].keys())
	times = np.array([[p.get(name, 0.0) for name in passes] for p in profiles])
	print("%d frames (after %d warm-up) at %dx%d in %.2f s (wall, with the Python callback); GPU ms per pass (mean over frames):" % (
			args.frames, max(args.warmup, 0), args.width, args.height, elapsed))
	for i, name in enumerate(passes):
		print("  %-18s %8.3f" % (name, times[:, i].mean()))
	print("  %-18s %8.3f" % ("total", times.sum(axis=1).mean()))

	fig, (ax_image, ax_times) = plt.subplots(1, 2, figsize=(11, 3.8), gridspec_kw={"width_ratios": [1, 1.3]})
	ax_image.imshow(preview(last, exposure=2.0))
	ax_image.set_title("last frame (%dx%d, two AreaLight3D)" % (args.width, args.height), fontsize=9)
	ax_image.axis("off")
	frames = np.arange(args.frames)
	for i, name in enumerate(passes):
		ax_times.plot(frames, times[:, i], label="%s (mean %.2f ms)" % (name, times[:, i].mean()), linewidth=1.4)
	ax_times.plot(frames, times.sum(axis=1), "k--", linewidth=1.0, label="total (mean %.2f ms)" % times.sum(axis=1).mean())
	ax_times.set_yscale("log")
	ax_times.set_xlabel("frame (the strip light sweeps a half circle)")
	ax_times.set_ylabel("GPU time per pass (ms, log scale)")
	ax_times.set_title("per-pass GPU times from godot_area.run_frames() on %s" % (ga.device_name() or "?"), fontsize=9)
	ax_times.legend(fontsize=7, loc="center right")
	ax_times.grid(alpha=0.3)
	fig.tight_layout()
	os.makedirs(os.path.dirname(os.path.abspath(args.png)), exist_ok=True)
	fig.savefig(args.png, dpi=90)
	print("wrote %s" % args.png)
	errors = ga.validation_error_count()
	ga.shutdown()
	return 1 if errors else 0


if __name__ == "__main__":
	sys.exit(main())
