#!/usr/bin/python3
# godot-area: charts and closing numbers of the shading-method sweep (`godot-area bench --sweep methods`).
#
#   /usr/bin/python3 misc/scripts/plot_methods.py SWEEP_CSV [--maps DIR] [--out doc/results]
#
# Writes OUT/methods_pareto.png (speed vs accuracy per method and sample count),
# OUT/methods_lights.png (GPU ms of the opaque pass vs number of lights), and, with --maps,
# OUT/methods_failure_<scene>.png (engine | reference | FLIP strips of each method on a failure scene).
# Prints the closing numbers of doc/methods.md as markdown.
# A CSV of the shape axis (`bench --sweep methods --shapes`, sections shape_timing / shape_error) gives
# OUT/methods_shapes_pareto.png instead (per shape: GPU ms per light vs mean relative RMSE, the Pareto
# front dashed) and the per-shape table of doc/methods.md §11 (cost, relative RMSE, FLIP, front).
import argparse
import csv
import os
import statistics

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
from chart_io import save_figure  # noqa: E402

ORDER = ["LTC", "LTC_POLYNOMIAL", "LTC_2LOBE", "MRP", "MC1", "MC4", "MC16", "SPOT", "OMNI"]
LABEL = {"LTC": "LTC (LUT)", "LTC_POLYNOMIAL": "LTC poly", "LTC_2LOBE": "LTC 2-lobe", "MRP": "MRP", "MC1": "MC 1", "MC4": "MC 4", "MC16": "MC 16", "SPOT": "spot", "OMNI": "omni"}


SHAPES = ["rectangle", "disk", "sphere", "tube"]
SHAPE_ORDER = ["LTC", "MRP", "MC8"]
SHAPE_LABEL = {"LTC": "LTC", "MRP": "MRP", "MC8": "MC 8"}


def load(path):
	timing, errors = {}, {}
	shape_timing, shape_errors = {}, {}
	res = None
	with open(path) as f:
		rows = list(csv.DictReader(f))
	for row in rows:
		if row["section"] == "shape_timing":
			shape_timing.setdefault((row["shape"], row["config"]), {})[int(row["lights"])] = float(row["gpu_ms_opaque"])
			res = (row["width"], row["height"])
		elif row["section"] == "shape_error":
			shape_errors.setdefault((row["shape"], row["config"]), []).append((float(row["rel_rmse"]), float(row["flip"])))
		elif row["section"] == "timing":
			timing.setdefault(row["config"], {})[int(row["lights"])] = float(row["gpu_ms_opaque"])
			res = (row["width"], row["height"])
		else:
			errors.setdefault(row["config"], {})[row["scene"]] = float(row["flip"])
	return timing, errors, res, shape_timing, shape_errors


def per_light(t):
	# Least-squares slope of GPU ms over the light count: ms per added light.
	xs = sorted(t)
	if len(xs) < 2:
		return float("nan")
	mx = sum(xs) / len(xs)
	my = sum(t[x] for x in xs) / len(xs)
	return sum((x - mx) * (t[x] - my) for x in xs) / sum((x - mx) ** 2 for x in xs)


def cost_per_light(t):
	# The slope over two or more light counts; one count: its time divided by the lights.
	if len(t) >= 2:
		return per_light(t)
	(n, ms), = t.items()
	return ms / n


def pareto(points):
	# points: (cost, error, name); the names no other point beats in both cost and error.
	front, best = [], float("inf")
	for x, y, c in sorted(points):
		if y < best:
			front.append(c)
			best = y
	return front


def shapes_chart(shape_timing, shape_errors, res, out):
	fig, axes = plt.subplots(2, 2, figsize=(8.0, 6.0), dpi=100)
	table = []
	for ax, shape in zip(axes.flat, SHAPES):
		pts = []
		for c in SHAPE_ORDER:
			if (shape, c) in shape_timing and (shape, c) in shape_errors:
				errs = shape_errors[(shape, c)]
				x = cost_per_light(shape_timing[(shape, c)])
				y = statistics.mean(e[0] for e in errs)
				flip = statistics.mean(e[1] for e in errs)
				pts.append((x, y, c))
				table.append((shape, c, x, y, flip, len(errs)))
				ax.scatter([x], [y], s=30)
				ax.annotate("%s (FLIP %.3f)" % (SHAPE_LABEL[c], flip), (x, y), textcoords="offset points", xytext=(4, 4), fontsize=8)
		front = pareto(pts)
		fp = sorted((x, y) for x, y, c in pts if c in front)
		if fp:
			ax.plot([p[0] for p in fp], [p[1] for p in fp], "k--", lw=0.8, label="Pareto front")
			ax.legend(fontsize=7)
		for i, row in enumerate(table):
			if row[0] == shape:
				table[i] = row + (row[1] in front,)
		ax.set_title(shape, fontsize=9)
		ax.set_xlabel("GPU ms per light (opaque pass)", fontsize=8)
		ax.set_ylabel("mean relative RMSE vs reference", fontsize=8)
		ax.grid(True, alpha=0.3)
	fig.suptitle("Shape x method: speed vs accuracy (%sx%s, lavapipe)" % res if res else "Shape x method: speed vs accuracy", fontsize=10)
	fig.tight_layout()
	save_figure(fig, os.path.join(out, "methods_shapes_pareto.png"))
	plt.close(fig)
	print("| shape | method | GPU ms per light | mean relative RMSE | mean LDR-FLIP | scenes | Pareto front |")
	print("|---|---|---|---|---|---|---|")
	for shape, c, x, y, flip, n, on_front in table:
		print("| %s | %s | %.3f | %.4f | %.4f | %d | %s |" % (shape, SHAPE_LABEL[c], x, y, flip, n, "yes" if on_front else "no"))


def main():
	ap = argparse.ArgumentParser()
	ap.add_argument("csv")
	ap.add_argument("--maps", default="")
	ap.add_argument("--out", default="doc/results")
	a = ap.parse_args()
	timing, errors, res, shape_timing, shape_errors = load(a.csv)
	os.makedirs(a.out, exist_ok=True)
	if shape_timing or shape_errors:
		if not shape_timing or not shape_errors:
			raise SystemExit("plot_methods.py: the shape chart needs both shape_timing and shape_error rows in %s" % a.csv)
		shapes_chart(shape_timing, shape_errors, res, a.out)
		if not timing:
			return
	configs = [c for c in ORDER if c in timing]

	# (b) GPU ms vs number of lights.
	fig, ax = plt.subplots(figsize=(6.4, 4.2), dpi=100)
	for c in configs:
		xs = sorted(timing[c])
		ax.plot(xs, [timing[c][x] for x in xs], marker="o", ms=3, label=LABEL[c])
	ax.set_xscale("log", base=2)
	ax.set_yscale("log")
	ax.set_xlabel("lights in view")
	ax.set_ylabel("GPU ms, opaque pass (median)")
	ax.set_title("Cost vs light count (%sx%s, lavapipe)" % res if res else "Cost vs light count")
	ax.grid(True, which="both", alpha=0.3)
	ax.legend(fontsize=8, ncol=2)
	fig.tight_layout()
	save_figure(fig, os.path.join(a.out, "methods_lights.png"))
	plt.close(fig)

	# (a) Pareto: per-light cost vs mean FLIP on the error scenes.
	fig, ax = plt.subplots(figsize=(6.4, 4.2), dpi=100)
	pts = []
	for c in configs:
		if c in errors and errors[c]:
			x = per_light(timing[c])
			y = statistics.mean(errors[c].values())
			pts.append((x, y, c))
			ax.scatter([x], [y], s=30)
	# Labels of points close to each other (e.g. LTC and LTC poly) alternate above and below.
	for i, (x, y, c) in enumerate(sorted(pts)):
		ax.annotate(LABEL[c], (x, y), textcoords="offset points", xytext=(4, 4 if i % 2 == 0 else -11), fontsize=8)
	front, best = [], float("inf")
	for x, y, c in sorted(pts):
		if y < best:
			front.append((x, y))
			best = y
	if front:
		ax.plot([p[0] for p in front], [p[1] for p in front], "k--", lw=0.8, label="Pareto front")
	ax.set_xscale("log")
	ax.set_xlabel("GPU ms per added light (opaque pass)")
	ax.set_ylabel("mean LDR-FLIP vs reference")
	ax.set_title("Speed vs accuracy")
	ax.grid(True, which="both", alpha=0.3)
	ax.legend(fontsize=8)
	fig.tight_layout()
	save_figure(fig, os.path.join(a.out, "methods_pareto.png"))
	plt.close(fig)

	# (c) Error maps of the failure scenes: one PNG per scene, one row per method.
	if a.maps:
		# Map files are CONFIG_SCENE.png; configs share prefixes (LTC, LTC_POLYNOMIAL, LTC_2LOBE), so the
		# longest matching config is stripped.
		prefixes = sorted(ORDER, key=len, reverse=True)
		scenes = set()
		for f in os.listdir(a.maps):
			if f.endswith(".png"):
				c = next((c for c in prefixes if f.startswith(c + "_")), None)
				if c:
					scenes.add(f[len(c) + 1:-4])
		scenes = sorted(scenes)
		for scene in scenes:
			rows = [(c, os.path.join(a.maps, "%s_%s.png" % (c, scene))) for c in ORDER if os.path.exists(os.path.join(a.maps, "%s_%s.png" % (c, scene)))]
			if not rows:
				continue
			img0 = mpimg.imread(rows[0][1])
			h, w = img0.shape[0], img0.shape[1]
			fig = plt.figure(figsize=(w / 100.0 + 1.1, (h / 100.0) * len(rows) + 0.35), dpi=100)
			for i, (c, p) in enumerate(rows):
				axi = fig.add_axes([1.1 / (w / 100.0 + 1.1), 1.0 - (i + 1) * (h / 100.0) / ((h / 100.0) * len(rows) + 0.35) - 0.3 / ((h / 100.0) * len(rows) + 0.35), (w / 100.0) / (w / 100.0 + 1.1), (h / 100.0) / ((h / 100.0) * len(rows) + 0.35)])
				axi.imshow(mpimg.imread(p), interpolation="nearest")
				axi.set_axis_off()
				flip = errors.get(c, {}).get(scene)
				fig.text(0.01, 1.0 - (i + 0.5) * (h / 100.0) / ((h / 100.0) * len(rows) + 0.35) - 0.3 / ((h / 100.0) * len(rows) + 0.35), "%s\nFLIP %.3f" % (LABEL[c], flip) if flip is not None else LABEL[c], fontsize=7, va="center")
			fig.text(0.5, 0.995, "%s: engine | reference | FLIP" % scene, ha="center", va="top", fontsize=8)
			save_figure(fig, os.path.join(a.out, "methods_failure_%s.png" % scene))
			plt.close(fig)

	# Closing numbers.
	def at(c, n):
		return timing.get(c, {}).get(n)

	print("| quantity | value |")
	print("|---|---|")
	for n in (16, 64):
		if at("LTC", n) and at("MRP", n):
			print("| LTC / MRP GPU time, %d lights | %.2f |" % (n, at("LTC", n) / at("MRP", n)))
	for n in (1, 16, 64):
		if at("LTC", n) and at("LTC_POLYNOMIAL", n):
			print("| LTC-poly / LTC-LUT GPU time, %d lights | %.2f |" % (n, at("LTC_POLYNOMIAL", n) / at("LTC", n)))
	for n in sorted(timing.get("LTC", {})):
		if at("SPOT", n):
			print("| area (LTC) / spot GPU time, %d lights | %.2f |" % (n, at("LTC", n) / at("SPOT", n)))
	if "LTC" in timing and "SPOT" in timing:
		print("| area (LTC) / spot, per added light | %.2f |" % (per_light(timing["LTC"]) / max(per_light(timing["SPOT"]), 1e-9)))
	for c in ORDER:
		if c in errors:
			print("| mean LDR-FLIP %s (%d scenes) | %.4f |" % (LABEL[c], len(errors[c]), statistics.mean(errors[c].values())))


if __name__ == "__main__":
	main()
