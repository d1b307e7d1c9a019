#!/usr/bin/python3
# godot-area: chart of the adaptive-shadow dolly benchmark (`godot-area bench --sweep dolly`, issue 7).
#
#   /usr/bin/python3 misc/scripts/plot_dolly.py DOLLY_CSV [--out doc/results]
#
# Writes OUT/dolly.png, four panels against the camera's distance to the penumbra (far on the left):
# total GPU ms per frame, shadow-map ms (with ADAPTIVE's reprojection and banding passes), visibility RMSE
# against the Embree reference, and the number of shadow maps. One line per shadow mode. Values of -1
# (a pass missing from the profile, no error computed) are left out. Prints the markdown table of
# doc/shadows.md (one column per camera position).
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from chart_io import save_figure  # noqa: E402

STYLES = {
	"ADAPTIVE": dict(color="tab:red", marker="o"),
	"HEURISTIC": dict(color="tab:purple", marker="s"),
	"FIXED_25": dict(color="tab:blue", marker="^"),
	"FIXED_81": dict(color="tab:green", marker="v"),
}


def load(path):
	modes = {}
	for row in csv.DictReader(open(path)):
		modes.setdefault(row["mode"], []).append(row)
	for rows in modes.values():
		rows.sort(key=lambda r: int(r["position"]))
	return modes


def series(rows, key):
	xs, ys = [], []
	for r in rows:
		v = float(r[key])
		if v >= 0.0:
			xs.append(float(r["distance"]))
			ys.append(v)
	return xs, ys


def main():
	parser = argparse.ArgumentParser(description=__doc__)
	parser.add_argument("csv")
	parser.add_argument("--out", default="doc/results")
	args = parser.parse_args()
	modes = load(args.csv)
	if not modes:
		raise SystemExit("plot_dolly.py: no rows in " + args.csv)
	distances = sorted({float(r["distance"]) for rows in modes.values() for r in rows})
	fig, axes = plt.subplots(2, 2, figsize=(11, 8))
	panels = [
		(axes[0][0], "total_ms", "total GPU ms per frame"),
		(axes[0][1], "shadow_maps_ms", "shadow-map pass, GPU ms"),
		(axes[1][0], "visibility_rmse", "visibility RMSE vs reference"),
		(axes[1][1], "maps", "shadow maps"),
	]
	for ax, key, title in panels:
		for mode, rows in modes.items():
			xs, ys = series(rows, key)
			if xs:
				ax.plot(xs, ys, label=mode, **STYLES.get(mode, {}))
		ax.set_title(title)
		ax.set_xscale("log")
		ax.set_xticks(distances)
		ax.set_xticklabels(["%.2g" % d for d in distances], fontsize=8)
		ax.minorticks_off()
		ax.invert_xaxis()
		ax.set_xlabel("camera distance to the penumbra (m), far \u2192 near")
		ax.grid(True, alpha=0.3)
	# ADAPTIVE's own passes on the shadow-map panel.
	rows = modes.get("ADAPTIVE", [])
	for key, style, label in (("reprojection_ms", ":", "ADAPTIVE reprojection"), ("banding_ms", "-.", "ADAPTIVE banding")):
		xs, ys = series(rows, key)
		if xs:
			axes[0][1].plot(xs, ys, linestyle=style, color="tab:red", label=label)
	for ax, _, _ in panels:
		ax.legend(fontsize=8)
	first = next(iter(modes.values()))[0]
	fig.suptitle("Dolly (thesis 6.4): %s x %s px, atlas %s, light moving (every map redrawn each frame)" % (first["width"], first["height"], first["atlas"]))
	fig.tight_layout()
	os.makedirs(args.out, exist_ok=True)
	out = os.path.join(args.out, "dolly.png")
	save_figure(fig, out, dpi=90)
	print("wrote " + out)
	# Markdown table for doc/shadows.md: one column per position, one row per mode and quantity.
	print("\n| distance (m) | " + " | ".join("%.2g" % d for d in sorted(distances, reverse=True)) + " |")
	print("|---|" + "---|" * len(distances))
	for key, label, fmt in (("maps", "maps", "%d"), ("shadow_maps_ms", "shadow maps ms", "%.1f"), ("reprojection_ms", "reprojection ms", "%.1f"),
			("banding_ms", "banding ms", "%.1f"), ("total_ms", "total GPU ms", "%.0f"), ("visibility_rmse", "visibility RMSE", "%.4f")):
		for mode, rows in modes.items():
			values = [float(r[key]) for r in rows]
			if all(v < 0.0 for v in values):
				continue
			cells = [(fmt % v) if v >= 0.0 else "\u2013" for v in values]
			print("| %s %s | %s |" % (mode, label, " | ".join(cells)))

if __name__ == "__main__":
	main()
