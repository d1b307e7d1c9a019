# godot-area: helpers shared by the pytest files in tests/python/ (not collected as tests):
# starting the engine, building a scene from nothing, reading an EXR header.
import os

import numpy as np

import godot_area as ga


def start_engine():
	"""Starts the engine once per process (GODOT_AREA_PY_BACKEND: 'rd', the default, or 'dummy')."""
	backend = os.environ.get("GODOT_AREA_PY_BACKEND", "rd")
	if ga.backend() == "none":
		ga.init(backend)
	assert ga.backend() == backend, (ga.backend(), backend)
	return ga


def look_at(eye, target, up=(0.0, 1.0, 0.0)):
	"""A 3x4 Transform3D (basis rows, then origin) whose -Z axis points from eye to target."""
	eye, target, up = np.asarray(eye, float), np.asarray(target, float), np.asarray(up, float)
	back = eye - target
	back /= np.linalg.norm(back)
	right = np.cross(up, back)
	right /= np.linalg.norm(right)
	new_up = np.cross(back, right)
	basis = np.stack([right, new_up, back], axis=1)  # Columns are the local axes.
	return np.hstack([basis, eye.reshape(3, 1)])


def build_scene():
	"""Floor, a box, a camera and two area lights (the key one casts shadows), from nothing."""
	root = ga.create("Node3D")
	root.name = "Scene"

	floor = root.add_child(ga.create("MeshInstance3D"))
	floor.name = "Floor"
	plane = ga.create("PlaneMesh")
	plane.size = (6, 6)
	floor.mesh = plane
	material = ga.create("StandardMaterial3D")
	material.albedo_color = (0.7, 0.7, 0.7)
	material.roughness = 0.5
	floor.material_override = material

	box = root.add_child(ga.create("MeshInstance3D"))
	box.name = "Box"
	box_mesh = ga.create("BoxMesh")
	box_mesh.size = (0.6, 0.6, 0.6)
	box.mesh = box_mesh
	box.position = (0.0, 0.3, 0.0)

	camera = root.add_child(ga.create("Camera3D"))
	camera.name = "Camera"
	camera.transform = look_at((0.0, 3.0, 4.0), (0.0, 0.0, 0.0))
	camera.fov = 60.0

	key = root.add_child(ga.create("AreaLight3D"))
	key.name = "Key"
	key.transform = look_at((0.0, 2.0, 0.5), (0.0, 0.0, 0.5), up=(0.0, 0.0, -1.0))
	key.area_size = (1.5, 1.0)
	key.light_energy = 2.0
	key.shadow_enabled = True

	fill = root.add_child(ga.create("AreaLight3D"))
	fill.name = "Fill"
	fill.transform = look_at((-2.0, 1.5, 1.0), (0.0, 0.0, 0.0))
	fill.area_size = (0.5, 0.5)
	fill.light_color = (0.6, 0.7, 1.0)
	return root


EXR_PIXEL_TYPES = {0: "uint", 1: "half", 2: "float"}


def exr_channel_types(path):
	"""{channel name: 'uint'|'half'|'float'} from an OpenEXR header (the 'channels' attribute)."""
	with open(path, "rb") as f:
		data = f.read(65536)
	assert data[:4] == b"\x76\x2f\x31\x01", "%s is not an OpenEXR file" % path
	pos = 8  # Magic number, version/flags.
	while data[pos] != 0:
		name_end = data.index(b"\0", pos)
		name = data[pos:name_end].decode()
		type_end = data.index(b"\0", name_end + 1)
		attr_type = data[name_end + 1:type_end].decode()
		size = int.from_bytes(data[type_end + 1:type_end + 5], "little")
		value = data[type_end + 5:type_end + 5 + size]
		if name == "channels" and attr_type == "chlist":
			channels, i = {}, 0
			while value[i] != 0:
				channel_end = value.index(b"\0", i)
				pixel_type = int.from_bytes(value[channel_end + 1:channel_end + 5], "little")
				channels[value[i:channel_end].decode()] = EXR_PIXEL_TYPES.get(pixel_type, "unknown")
				i = channel_end + 1 + 16  # pixel type, pLinear + 3 reserved, x/y sampling.
			return channels
		pos = type_end + 5 + size
	raise AssertionError("%s has no channel list" % path)
