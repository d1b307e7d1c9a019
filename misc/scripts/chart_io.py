# godot-area: atomic chart writes for the plot_*.py scripts (issue 20: no partial file on a failed write).
#
# save_figure(fig, path) renders the figure into a temporary file in the target's folder, fsyncs it and
# renames it over the target, so a reader sees the old chart or the whole new one; on any failure the
# temporary is removed and the exception propagates (the script, and so the sweep, exits non-zero).
import os
import tempfile


def save_figure(fig, path, **kwargs):
	folder = os.path.dirname(os.path.abspath(path))
	fmt = kwargs.pop("format", None) or os.path.splitext(path)[1].lstrip(".") or "png"
	fd, tmp = tempfile.mkstemp(prefix=".chart_", suffix="." + fmt, dir=folder)
	try:
		with os.fdopen(fd, "wb") as f:
			fig.savefig(f, format=fmt, **kwargs)
			f.flush()
			os.fsync(f.fileno())
		os.replace(tmp, path)
	except BaseException:
		try:
			os.unlink(tmp)
		except OSError:
			pass
		raise
