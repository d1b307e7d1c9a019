#!/usr/bin/python3
# godot-area: charts of the image-space radiosity sweep (`godot-area bench --sweep isr`, issue 22).
#
#   /usr/bin/python3 misc/scripts/plot_isr.py QUALITY_CSV --timing TIMING_CSV [--out doc/results]
#
# Writes OUT/isr_quality.png (per frame of the camera paths: mean error of direct-only and ISR against the
# one-bounce truth, and the share of indirectly lit pixels ISR improves) and OUT/isr_timing.png (ISR pass ms
# and ISR / opaque ratio against the sample count, one line per resolution). Prints markdown tables.
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from chart_io import save_figure  # noqa: E402


def main():
	parser = argparse.ArgumentParser()
	parser.add_argument("quality_csv")
	parser.add_argument("--timing", required=True)
	parser.add_argument("--out", default=None)
	args = parser.parse_args()
	out = args.out or os.path.dirname(os.path.abspath(args.quality_csv))
	quality = list(csv.DictReader(open(args.quality_csv)))
	timing = list(csv.DictReader(open(args.timing)))

	fig, axes = plt.subplots(1, 2, figsize=(11, 4))
	labels = ["%s %s" % (r["scene"], r["frame"]) for r in quality]
	xs = range(len(quality))
	axes[0].plot(xs, [float(r["mean_error_dl"]) for r in quality], "o-", label="direct only")
	axes[0].plot(xs, [float(r["mean_error_isr"]) for r in quality], "s-", label="ISR")
	axes[0].set_ylabel("mean error vs one-bounce truth (eq. 19)")
	axes[1].bar(xs, [100.0 * float(r["improved_share"]) for r in quality], color="tab:green")
	axes[1].set_ylabel("indirectly lit pixels improved (%)")
	axes[1].set_ylim(0, 100)
	for ax in axes:
		ax.set_xticks(list(xs))
		ax.set_xticklabels(labels, rotation=45, ha="right")
		ax.grid(alpha=0.3)
	axes[0].legend()
	fig.tight_layout()
	save_figure(fig, os.path.join(out, "isr_quality.png"), dpi=110)

	fig, axes = plt.subplots(1, 2, figsize=(11, 4))
	sizes = sorted({(int(r["width"]), int(r["height"])) for r in timing})
	for w, h in sizes:
		rows = sorted([r for r in timing if int(r["width"]) == w and int(r["height"]) == h and int(r["samples"]) > 0], key=lambda r: int(r["samples"]))
		n = [int(r["samples"]) for r in rows]
		axes[0].plot(n, [float(r["isr_ms"]) for r in rows], "o-", label="%dx%d" % (w, h))
		axes[1].plot(n, [100.0 * float(r["isr_over_opaque"]) for r in rows], "o-", label="%dx%d" % (w, h))
	axes[0].set_ylabel("ISR pass ms (lavapipe: wall clock)")
	axes[1].set_ylabel("ISR / opaque pass (%)")
	for ax in axes:
		ax.set_xlabel("samples per pixel")
		ax.grid(alpha=0.3)
		ax.legend()
	fig.tight_layout()
	save_figure(fig, os.path.join(out, "isr_timing.png"), dpi=110)

	print("| scene | frame | improved | mean error DL | mean error ISR | gain | Pearson DL | Pearson ISR |")
	print("|---|---|---|---|---|---|---|---|")
	for r in quality:
		print("| %s | %s | %.2f %% | %.5f | %.5f | %.1f %% | %.4f | %.4f |" % (r["scene"], r["frame"], 100.0 * float(r["improved_share"]), float(r["mean_error_dl"]),
				float(r["mean_error_isr"]), 100.0 * float(r["mean_error_gain"]), float(r["pearson_dl"]), float(r["pearson_isr"])))
	print()
	print("| resolution | samples | opaque ms | ISR ms | ISR / opaque | CPU ms/frame |")
	print("|---|---|---|---|---|---|")
	for r in timing:
		print("| %sx%s | %s | %.3f | %.3f | %.1f %% | %.2f |" % (r["width"], r["height"], r["samples"], float(r["opaque_ms"]), float(r["isr_ms"]),
				100.0 * float(r["isr_over_opaque"]), float(r["cpu_ms_per_frame"])))


if __name__ == "__main__":
	main()
