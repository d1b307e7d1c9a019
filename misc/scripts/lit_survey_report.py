#!/usr/bin/env python3
"""Classifies the previews of misc/scripts/scene_lit_survey.sh and writes its montage.

usage: lit_survey_report.py WORK [MONTAGE.png]   (default montage: WORK/montage.png)

A scene "renders lit" when its render exited 0 and its 8-bit preview (the tonemapped PNG of
`godot-area render --png`, 96x54) has
  - mean Rec. 709 luma (sRGB-encoded values, 0..1) of at least MIN_MEAN (not black), and
  - a luma standard deviation of at least MIN_STD (not one flat colour: a clear colour or a uniformly
    ambient-lit view has almost none; shading, shadows, sky gradients and textures have more).
Prints a markdown table (scene, rc, mean, std, class) and the counts; the montage holds every
rendered preview, 8 per row, in path order, with a red bar under the unlit ones.
"""

import os
import sys

import numpy as np
from PIL import Image, ImageDraw

MIN_MEAN = 0.03
MIN_STD = 0.02
THUMB_W, THUMB_H, PER_ROW = 96, 54, 8


def classify(png_path, rc):
	if rc != 0 or not os.path.exists(png_path):
		return None, None, "failed (rc %d)" % rc
	img = np.asarray(Image.open(png_path).convert("RGB"), dtype=np.float64) / 255.0
	luma = 0.2126 * img[..., 0] + 0.7152 * img[..., 1] + 0.0722 * img[..., 2]
	mean, std = float(luma.mean()), float(luma.std())
	if mean < MIN_MEAN:
		return mean, std, "black"
	if std < MIN_STD:
		return mean, std, "flat"
	return mean, std, "lit"


def main():
	work = sys.argv[1]
	montage_path = sys.argv[2] if len(sys.argv) > 2 else os.path.join(work, "montage.png")
	rows = []
	with open(os.path.join(work, "rc.txt")) as f:
		for line in f:
			scene, rc = line.rsplit(" ", 1)
			base = os.path.join(work, "out", scene.replace("/", "_")[: -len(".tscn")])
			mean, std, cls = classify(base + ".png", int(rc))
			rows.append((scene, int(rc), mean, std, cls, base + ".png"))
	print("| scene | rc | mean luma | luma std | class |")
	print("|---|---|---|---|---|")
	for scene, rc, mean, std, cls, _ in rows:
		m = "%.3f" % mean if mean is not None else "-"
		s = "%.3f" % std if std is not None else "-"
		print("| %s | %d | %s | %s | %s |" % (scene, rc, m, s, cls))
	counts = {}
	for r in rows:
		counts[r[4].split(" ")[0]] = counts.get(r[4].split(" ")[0], 0) + 1
	lit = counts.get("lit", 0)
	print("\n%d scenes: %s; lit %.1f %% (MIN_MEAN %.2f, MIN_STD %.2f)" % (len(rows), ", ".join("%s %d" % kv for kv in sorted(counts.items())), 100.0 * lit / max(len(rows), 1), MIN_MEAN, MIN_STD))
	shown = [r for r in rows if r[2] is not None]
	if not shown:
		return
	cols = PER_ROW
	n_rows = (len(shown) + cols - 1) // cols
	sheet = Image.new("RGB", (cols * THUMB_W, n_rows * (THUMB_H + 3)), (0, 0, 0))
	draw = ImageDraw.Draw(sheet)
	for i, r in enumerate(shown):
		x, y = (i % cols) * THUMB_W, (i // cols) * (THUMB_H + 3)
		sheet.paste(Image.open(r[5]).convert("RGB").resize((THUMB_W, THUMB_H)), (x, y))
		if r[4] != "lit":
			draw.rectangle([x, y + THUMB_H, x + THUMB_W - 1, y + THUMB_H + 2], fill=(220, 30, 30))
	tmp = montage_path + ".tmp.png"
	sheet.save(tmp, optimize=True)
	os.replace(tmp, montage_path)  # No partial file on failure.
	print("montage: %s (%d thumbnails)" % (montage_path, len(shown)))


if __name__ == "__main__":
	main()
