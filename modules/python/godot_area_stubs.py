# godot-area: writes godot_area.pyi, the stub file editors read for completion and type
# checking, from the live module (ClassDB classes, math types, functions). SConstruct runs
# it after building the extension: bin/python[_VARIANT]/godot_area.pyi.
import inspect as _inspect
import os as _os
import re as _re
import sys as _sys

_MATH = ("Vector2", "Vector3", "Vector4", "Color", "Basis", "Transform3D")


def _annotation(p_value):
	if p_value is _inspect.Parameter.empty or p_value is _inspect.Signature.empty:
		return ""
	return p_value if isinstance(p_value, str) else getattr(p_value, "__name__", str(p_value))


def _signature_text(p_function, p_self=True):
	try:
		sig = _inspect.signature(p_function)
	except (TypeError, ValueError):
		return "(self, *args, **kwargs)" if p_self else "(*args, **kwargs)", ""
	parts = []
	for param in sig.parameters.values():
		text = param.name
		if param.kind == param.VAR_POSITIONAL:
			text = "*" + text
		elif param.kind == param.VAR_KEYWORD:
			text = "**" + text
		ann = _annotation(param.annotation)
		if ann:
			text += ": " + ann
		if param.default is not param.empty:
			text += " = ..."
		parts.append(text)
	if p_self and (not parts or parts[0].split(":")[0] != "self"):
		parts.insert(0, "self")
	return "(" + ", ".join(parts) + ")", _annotation(sig.return_annotation)


def _pybind_signature(p_doc, p_name):
	"""'name(a: str = 'rd') -> None' from a pybind11 docstring's first line."""
	line = (p_doc or "").strip().splitlines()[0] if p_doc and p_doc.strip() else ""
	match = _re.match(r"^%s(\(.*\))(?: -> (.+))?$" % _re.escape(p_name), line)
	if not match:
		return "(*args, **kwargs)", "typing.Any"
	args = _re.sub(r" = [^,)]+(?=[,)])", " = ...", match.group(1))
	args = _re.sub(r"godot_area\.", "", args)
	args = args.replace("numpy.ndarray[numpy.float32]", "numpy.ndarray").replace("object", "typing.Any").replace("List[", "list[")
	args = _re.sub(r"\bself: [A-Za-z_.]+", "self", args)
	ret = (match.group(2) or "None").replace("godot_area.", "").replace("numpy.ndarray[numpy.float32]", "numpy.ndarray")
	ret = _re.sub(r"\bobject\b", "typing.Any", ret).replace("List[", "list[")
	return args, ret


def _doc_lines(p_doc, p_indent):
	if not p_doc:
		return []
	first = p_doc.strip().splitlines()[0].replace('"""', "'''").replace("\\", "\\\\")
	return ['%s"""%s"""' % (p_indent, first)]


def _class_stub(p_module, p_cls):
	out = []
	base = p_cls.__mro__[1]
	base_name = base.__name__ if getattr(p_module, base.__name__, None) is base else ""
	out.append("class %s%s:" % (p_cls.__name__, "(%s)" % base_name if base_name else ""))
	out.extend(_doc_lines(p_cls.__doc__, "\t"))
	for enum_name, enum_class in sorted(getattr(p_cls, "_enums", {}).items()) if "_enums" in p_cls.__dict__ else []:
		out.append("\tclass %s(enum.IntEnum):" % enum_name)
		for member in enum_class:
			out.append("\t\t%s = %d" % (member.name, int(member)))
		for member in enum_class:
			out.append("\t%s: typing.ClassVar[%s.%s]" % (member._full_name, p_cls.__name__, enum_name))
	for name, value in sorted(p_cls.__dict__.items()):
		if isinstance(value, int) and not isinstance(value, bool) and name.isupper() and not hasattr(value, "_full_name"):
			out.append("\t%s: typing.ClassVar[int]" % name)
	api = p_cls.__dict__.get("_engine_api")
	if api:
		for prop in api["properties"]:
			if prop["name"] not in p_cls.__dict__:
				continue
			enum_info = p_cls._enum_properties.get(prop["name"])
			if enum_info and enum_info[0] is not None:
				kind = enum_info[0].__qualname__
			elif prop["type_name"] == "Object":
				kind = " | ".join((prop["class_name"] or "Object").split(",")) + " | None"
			else:
				kind = {"bool": "bool", "int": "int", "float": "float", "String": "str"}.get(prop["type_name"], prop["type_name"])
			out.append("\t%s: %s" % (prop["name"], kind))
		if api["instantiable"]:
			out.append("\tdef __init__(self, **properties: typing.Any) -> None: ...")
	for name, value in sorted(p_cls.__dict__.items()):
		if name.startswith("_") and name not in ("__init__",):
			continue
		if name == "__init__" and api:
			continue
		if callable(value) and not isinstance(value, type):
			if type(value).__name__ == "instancemethod" or not hasattr(value, "__signature__") and not _inspect.isfunction(value):
				args, ret = _pybind_signature(getattr(value, "__doc__", ""), name)
			else:
				args, ret = _signature_text(value)
			out.append("\tdef %s%s -> %s: ..." % (name, args, ret or "typing.Any"))
	if len(out) == 1 or (len(out) == 2 and out[1].startswith('\t"""')):
		out.append("\t...")
	return out


def _math_stub(p_cls):
	out = ["class %s:" % p_cls.__name__]
	out.extend(_doc_lines(p_cls.__doc__, "\t"))
	for component in getattr(p_cls, "_names", ()):
		out.append("\t%s: float" % component)
	if p_cls.__name__ == "Basis":
		out.extend(["\tx: Vector3", "\ty: Vector3", "\tz: Vector3"])
	if p_cls.__name__ == "Transform3D":
		out.extend(["\tbasis: Basis", "\torigin: Vector3"])
	for name in sorted(dir(p_cls)):
		value = getattr(p_cls, name)
		if name.isupper():
			out.append("\t%s: typing.ClassVar[%s]" % (name, p_cls.__name__))
		elif name.startswith("_") and name not in ("__init__", "__add__", "__sub__", "__mul__", "__truediv__", "__neg__", "__getitem__", "__len__", "__iter__", "__eq__", "__array__"):
			continue
		elif _inspect.isfunction(value) or isinstance(_inspect.getattr_static(p_cls, name), staticmethod):
			static = isinstance(_inspect.getattr_static(p_cls, name), staticmethod)
			args, ret = _signature_text(value, p_self=not static)
			if static:
				out.append("\t@staticmethod")
			out.append("\tdef %s%s -> %s: ..." % (name, args, ret or "typing.Any"))
	return out


def write_stubs(p_path):
	"""Writes the stub file for the loaded module to p_path (atomically: a temporary file renamed)."""
	module = _sys.modules["godot_area"]
	lines = ["# Generated by godot_area._write_stubs() at build time (SConstruct). Do not edit.", "import enum", "import typing", "", "import numpy", ""]
	for name in _MATH:
		lines.extend(_math_stub(getattr(module, name)))
		lines.append("")
	classes = [v for v in vars(module).values() if isinstance(v, type) and issubclass(v, module.Object)]
	classes.sort(key=lambda c: (len(c.__mro__), c.__name__))
	for cls in classes:
		lines.extend(_class_stub(module, cls))
		lines.append("")
	tree = module.SceneTree
	lines.extend(_class_stub(module, tree))
	lines.append("")
	for name, value in sorted(vars(module).items()):
		if name.startswith("_") or isinstance(value, type) or not callable(value):
			continue
		args, ret = _pybind_signature(value.__doc__, name)
		lines.append("def %s%s -> %s: ..." % (name, args, ret))
	text = "\n".join(lines) + "\n"
	compile(text, p_path, "exec")  # Fails the build rather than writing a stub that does not parse.
	tmp = p_path + ".tmp"
	with open(tmp, "w", encoding="utf-8") as f:
		f.write(text)
	_os.replace(tmp, p_path)
	return len(classes)
