# godot-area: pytest fixtures for the Python module `godot_area` (modules/python).
#
#   PYTHONPATH=bin/python_<variant> GODOT_AREA_CLI=bin/godot-area.<variant> PYTHONDONTWRITEBYTECODE=1 \
#       /usr/bin/python3 -m pytest -q -p no:cacheprovider tests/python
#
# The doctest case "[Python] ..." (tests/modules/test_python_module.cpp) runs exactly that, so the
# README test command (misc/scripts/test.sh) is the only entry point.
# GODOT_AREA_PY_BACKEND=dummy runs everything but rendering (machines without Vulkan).
import os

import pytest

import godot_area as ga
from ga_helpers import start_engine


@pytest.fixture(scope="session", autouse=True)
def engine():
	"""The engine for the whole run (started at collection at the latest); at the end it is shut
	down and no Vulkan validation error may have happened anywhere in the run."""
	start_engine()
	yield ga
	validation_errors = ga.validation_error_count()
	ga.shutdown()
	assert ga.backend() == "none"
	assert validation_errors == 0, "%d Vulkan validation error(s) during the Python tests (GODOT_AREA_VALIDATION=1 prints them)" % validation_errors


@pytest.fixture
def rd(engine):
	"""The engine on the Vulkan backend (tests that render skip on 'dummy')."""
	if ga.backend() != "rd":
		pytest.skip("backend is '%s': no rendering" % ga.backend())
	return ga


@pytest.fixture
def tree(rd):
	"""The process-wide SceneTree, emptied again after the test."""
	t = ga.get_tree()
	assert t.root.get_child_count() == 0, "a previous test left nodes in the tree"
	yield t
	for child in t.root.get_children():
		t.root.remove_child(child)
		child.free()


@pytest.fixture
def cli():
	"""Path of the command-line binary built with this module: GODOT_AREA_CLI (set by the doctest
	case), else the one next to the module (bin/python_<variant>/ -> bin/godot-area.<variant>)."""
	path = os.environ.get("GODOT_AREA_CLI")
	if not path:
		module_dir = os.path.dirname(os.path.abspath(ga.__file__))
		leaf = os.path.basename(module_dir)
		variant = leaf[len("python_"):] if leaf.startswith("python_") else ""
		path = os.path.join(os.path.dirname(module_dir), "godot-area" + ("." + variant if variant else ""))
	assert os.access(path, os.X_OK), "the CLI binary %s is missing: build it (scons builds it by default) or set GODOT_AREA_CLI" % path
	return path
