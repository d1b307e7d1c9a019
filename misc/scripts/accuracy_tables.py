#!/usr/bin/python3
# godot-area: markdown tables from an accuracy-suite CSV (modules/accuracy, `bench --accuracy --csv F`):
# mean / worst LDR-FLIP and RMSE per method and placement, per light size, per receiver, and the
# worst scenes. Usage: /usr/bin/python3 misc/scripts/accuracy_tables.py doc/results/accuracy_ltc_96.csv
import csv
import sys
from collections import OrderedDict


def table(rows, key, title):
	groups = OrderedDict()
	for r in rows:
		groups.setdefault((r["method_name"], key(r)), []).append(r)
	print("| method | %s | scenes | FLIP mean | FLIP worst | RMSE mean | RMSE worst | SSIM mean |" % title)
	print("|---|---|---|---|---|---|---|---|")
	for (method, k), g in groups.items():
		flip = [float(r["flip"]) for r in g]
		rmse = [float(r["rmse"]) for r in g]
		ssim = [float(r["ssim"]) for r in g]
		print("| %s | %s | %d | %.4f | %.4f | %.4f | %.4f | %.4f |" % (method, k, len(g), sum(flip) / len(g), max(flip), sum(rmse) / len(g), max(rmse), sum(ssim) / len(g)))
	print()


def main():
	if len(sys.argv) != 2:
		sys.stderr.write("usage: accuracy_tables.py SUITE.csv\n")
		return 2
	with open(sys.argv[1], newline="") as f:
		rows = list(csv.DictReader(f))
	if not rows:
		sys.stderr.write("no rows in %s\n" % sys.argv[1])
		return 1
	table(rows, lambda r: r["placement"], "placement")
	table(rows, lambda r: "%sx%s" % (r["light_width"], r["light_height"]), "light size")
	table(rows, lambda r: "%s m%s" % (r["receiver"], r["metallic"]), "receiver, metallic")
	worst = sorted(rows, key=lambda r: -float(r["flip"]))[:12]
	print("| worst scenes (FLIP) | method | FLIP | RMSE | SSIM | reference samples/pixel |")
	print("|---|---|---|---|---|---|")
	for r in worst:
		print("| %s | %s | %.4f | %.4f | %.4f | %s |" % (r["scene_id"], r["method_name"], float(r["flip"]), float(r["rmse"]), float(r["ssim"]), r["reference_samples_per_pixel"]))
	ref = [float(r["reference_ms"]) for r in rows if r["method"] == rows[0]["method"]]
	eng = [float(r["engine_ms"]) for r in rows]
	print()
	print("reference: %.0f ms per image (mean of %d, %sx%s); engine: %.1f ms per frame (mean wall time of draw())" % (sum(ref) / len(ref), len(ref), rows[0]["resolution"], rows[0]["resolution"], sum(eng) / len(eng)))
	return 0


if __name__ == "__main__":
	sys.exit(main())
