#!/usr/bin/python3
# godot-area: charts and tables of the area soft-shadow sweep (`godot-area bench --sweep shadows`).
#
#   /usr/bin/python3 misc/scripts/plot_shadows.py SWEEP_CSV [--out doc/results]
#
# Writes OUT/shadows_error.png (visibility RMSE vs number of maps, one line per atlas size, one panel
# per shadow_blur, the one-map PCSS baseline dashed) and OUT/shadows_timing.png (GPU ms of the shadow
# pass vs number of maps with a least-squares line per atlas). Prints the markdown tables of
# doc/shadows.md: errors, the optimum per atlas size and blur, timings and the cost per map.
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from chart_io import save_figure  # noqa: E402


def load(path):
	errors, pcss, timing, fixed, tiles = {}, {}, {}, {}, {}
	for row in csv.DictReader(open(path)):
		atlas, maps, blur = int(row["atlas"]), int(row["maps"]), float(row["blur"])
		if row["section"] == "error" and row["mode"] == "PCSS":
			pcss[(atlas, blur)] = float(row["visibility_rmse"])
		elif row["section"] == "error":
			errors.setdefault(blur, {}).setdefault(atlas, {})[maps] = float(row["visibility_rmse"])
			tiles[(atlas, maps)] = int(row["tile"])
		elif row["section"] == "timing":
			timing.setdefault(atlas, {})[maps] = float(row["shadow_ms"])
			tiles[(atlas, maps)] = int(row["tile"])
		elif row["section"] == "timing_fixed_tile":
			fixed.setdefault((atlas, int(row["tile"])), {})[maps] = float(row["shadow_ms"])
	return errors, pcss, timing, fixed, tiles


def fit(xs, ys):
	n = len(xs)
	mx, my = sum(xs) / n, sum(ys) / n
	sxx = sum((x - mx) ** 2 for x in xs)
	slope = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx if sxx > 0 else 0.0
	return slope, my - slope * mx


def main():
	ap = argparse.ArgumentParser()
	ap.add_argument("csv")
	ap.add_argument("--out", default="doc/results")
	args = ap.parse_args()
	errors, pcss, timing, fixed, tiles = load(args.csv)
	os.makedirs(args.out, exist_ok=True)
	colors = ["tab:blue", "tab:orange", "tab:green", "tab:red"]

	if errors:
		blurs = sorted(errors)
		fig, axes = plt.subplots(1, len(blurs), figsize=(4.2 * len(blurs), 3.6), sharey=True, squeeze=False)
		for ax, blur in zip(axes[0], blurs):
			for k, atlas in enumerate(sorted(errors[blur])):
				pts = sorted(errors[blur][atlas].items())
				ax.plot([p[0] for p in pts], [p[1] for p in pts], "o-", color=colors[k % 4], label=f"atlas {atlas}")
				for m, e in pts:
					ax.annotate(f"{tiles[(atlas, m)]}", (m, e), textcoords="offset points", xytext=(3, 4), fontsize=7, color=colors[k % 4])
				if (atlas, blur) in pcss:
					ax.axhline(pcss[(atlas, blur)], ls="--", lw=1, color=colors[k % 4], label=f"PCSS 1 map, {atlas}")
			ax.set_xscale("log")
			ax.set_xticks([4, 9, 25, 49, 81])
			ax.set_xticklabels(["4", "9", "25", "49", "81"])
			ax.set_xlabel("shadow maps (labels: tile px)")
			ax.set_title(f"shadow_blur {blur:g} (PCF radius {2 * blur:g} texels)")
			ax.grid(alpha=0.3)
		axes[0][0].set_ylabel("visibility RMSE vs Embree reference")
		axes[0][-1].legend(fontsize=7)
		fig.tight_layout()
		save_figure(fig, os.path.join(args.out, "shadows_error.png"), dpi=110)

		print("| shadow_blur | atlas | " + " | ".join(f"{m} maps" for m in sorted(next(iter(errors[blurs[0]].values())))) + " | PCSS (1 map) | optimum |")
		print("|---|---|" + "---|" * (len(next(iter(errors[blurs[0]].values()))) + 2))
		for blur in blurs:
			for atlas in sorted(errors[blur]):
				row = errors[blur][atlas]
				best = min(row, key=row.get)
				cells = " | ".join(f"{row[m]:.4f} (tile {tiles[(atlas, m)]})" for m in sorted(row))
				p = pcss.get((atlas, blur))
				print(f"| {blur:g} | {atlas} | {cells} | {p:.4f} | {best} maps |" if p is not None else f"| {blur:g} | {atlas} | {cells} | - | {best} maps |")

	if timing:
		fig, ax = plt.subplots(figsize=(6.0, 4.0))
		print()
		print("Sweep tiles (tile px shrinks as maps grow):")
		print()
		print("| atlas | " + " | ".join(f"{m} maps" for m in sorted(next(iter(timing.values())))) + " |")
		print("|---|" + "---|" * len(next(iter(timing.values()))))
		for k, atlas in enumerate(sorted(timing)):
			pts = sorted(timing[atlas].items())
			xs, ys = [p[0] for p in pts], [p[1] for p in pts]
			ax.plot(xs, ys, "o-", color=colors[k % 4], label=f"atlas {atlas}, sweep tiles")
			print(f"| {atlas} | " + " | ".join(f"{y:.2f} (tile {tiles[(atlas, m)]})" for m, y in pts) + " |")
		if fixed:
			print()
			print("Fixed tile size (slope = cost per map):")
			print()
			print("| atlas | tile | " + " | ".join(f"{m} maps" for m in sorted(next(iter(fixed.values())))) + " | ms per map (fit) | intercept |")
			print("|---|---|" + "---|" * (len(next(iter(fixed.values()))) + 2))
			for k, (atlas, tile) in enumerate(sorted(fixed)):
				pts = sorted(fixed[(atlas, tile)].items())
				xs, ys = [p[0] for p in pts], [p[1] for p in pts]
				slope, icpt = fit(xs, ys)
				ax.plot(xs, ys, "s", color=colors[k % 4], mfc="none", label=f"atlas {atlas}, tile {tile}: {slope:.3f} ms/map")
				ax.plot([0, max(xs)], [icpt, icpt + slope * max(xs)], "--", lw=1, color=colors[k % 4])
				print(f"| {atlas} | {tile} | " + " | ".join(f"{y:.2f}" for y in ys) + f" | {slope:.3f} | {icpt:.2f} |")
		ax.set_xlabel("shadow maps redrawn per frame")
		ax.set_ylabel("GPU ms, area_shadows pass")
		ax.set_title("Shadow pass cost (lavapipe)")
		ax.grid(alpha=0.3)
		ax.legend(fontsize=8)
		fig.tight_layout()
		save_figure(fig, os.path.join(args.out, "shadows_timing.png"), dpi=110)


if __name__ == "__main__":
	main()
