# godot-area: one Python class per ClassDB class, generated when `godot_area` is imported
# (embedded into the extension at build time, like godot_area_math.py).
#
#   type(light) is ga.AreaLight3D; isinstance(light, ga.Light3D)
#   light.area_size.x = 2                   # ClassDB properties (bound values write back)
#   light.set_area_size((2, 1))             # ClassDB methods, with signatures
#   light.area_shading_method = ga.AreaLight3D.AreaShadingMethod.MRP   # or AREA_SHADING_MRP
#   help(ga.AreaLight3D)                    # the class reference (doc/classes/*.xml)
#
# `_module` is the extension module; it provides Object and Node (pybind11 classes, which
# become the generated Object and Node), _class_api() (ClassDB, no inheritance),
# _class_docs() (the XML class reference) and _set_class_map().
import enum as _enum
import inspect as _inspect
import keyword as _keyword
import re as _re
import xml.etree.ElementTree as _xml

_VARIANT_TYPES = {
	"Nil": "None",
	"bool": "bool",
	"int": "int",
	"float": "float",
	"String": "str",
	"Vector2": "Vector2",
	"Vector3": "Vector3",
	"Color": "Color",
	"Transform3D": "Transform3D",
	"Object": "Object",
	"Variant": "typing.Any",
	"void": "None",
}
_USAGE_GROUP_MARKERS = (1 << 6) | (1 << 7) | (1 << 8)
_HINT_ENUM = 2


def _bbcode_to_text(p_text):
	"""Godot's class-reference BBCode as plain text for docstrings."""
	text = _re.sub(r"\[(?:member|method|constant|enum|signal) ([^\]]+)\]", r"\1", p_text)
	text = _re.sub(r"\[/?(?:code|b|i|kbd|codeblock|codeblocks|gdscript|csharp)\]", "`", text)
	text = text.replace("``", "")
	text = _re.sub(r"\[([A-Z][A-Za-z0-9]*)\]", r"\1", text)
	lines = [line.strip() for line in text.strip().splitlines()]
	return "\n".join(lines)


def _parse_docs(p_xml_texts):
	docs = {}
	for text in p_xml_texts:
		root = _xml.fromstring(text)
		entry = {
			"brief": _bbcode_to_text(root.findtext("brief_description") or ""),
			"description": _bbcode_to_text(root.findtext("description") or ""),
			"members": {},
			"methods": {},
			"constants": {},
		}
		for member in root.iter("member"):
			entry["members"][member.get("name")] = {
				"text": _bbcode_to_text(member.text or ""),
				"enum": member.get("enum", ""),
				"default": member.get("default"),
			}
		for method in root.iter("method"):
			entry["methods"][method.get("name")] = _bbcode_to_text(method.findtext("description") or "")
		for constant in root.iter("constant"):
			entry["constants"][constant.get("name")] = _bbcode_to_text(constant.text or "")
		docs[root.get("name")] = entry
	return docs


def _snake(p_camel):
	return _re.sub(r"(?<!^)(?=[A-Z])", "_", p_camel).lower()


def _enum_short_names(p_names):
	"""AREA_SHADING_LTC, AREA_SHADING_MRP -> LTC, MRP (the common underscore prefix removed)."""
	if len(p_names) < 2:
		return list(p_names)
	parts = [n.split("_") for n in p_names]
	common = 0
	while all(len(p) > common + 1 for p in parts) and len(set(p[common] for p in parts)) == 1:
		common += 1
	short = ["_".join(p[common:]) for p in parts]
	if any(not s or s[0].isdigit() for s in short):
		return list(p_names)
	return short


def _hint_enum_items(p_hint_string):
	"""'A,B:5,C' -> [('A', 0), ('B', 5), ('C', 6)] (Godot's PROPERTY_HINT_ENUM syntax)."""
	items = []
	value = 0
	for part in p_hint_string.split(","):
		name, _, explicit = part.partition(":")
		if explicit.strip():
			value = int(explicit)
		items.append((name.strip(), value))
		value += 1
	return items


class _Bound:
	"""Writes a changed value read from a property back through the property."""

	__slots__ = ("owner", "name")

	def __init__(self, p_owner, p_name):
		self.owner = p_owner
		self.name = p_name

	def __call__(self, p_value):
		self.owner.set(self.name, p_value)


def _make_property(p_class_name, p_info, p_enum, p_doc):
	name = p_info["name"]

	def fget(self):
		value = self.get(name)
		if p_enum is not None and isinstance(value, int):
			try:
				return p_enum(value)
			except ValueError:
				return value
		bind = getattr(value, "_bind", None)
		if bind is not None:
			bind(_Bound(self, name))
		return value

	fget.__name__ = name
	return property(fget, doc=p_doc)


def _enum_value(p_class_name, p_property, p_enum, p_items, p_value):
	"""An enum property's value from a member, an int, or a member/label name."""
	if p_enum is not None:
		allowed = ", ".join("%s.%s (%d)" % (p_enum.__name__, m.name, int(m)) for m in p_enum)
	else:
		allowed = ", ".join("'%s' (%d)" % (label, v) for label, v in p_items)
	if isinstance(p_value, bool) or not isinstance(p_value, (int, str)) and not hasattr(p_value, "__index__"):
		raise TypeError("%s.%s is an enum (%s): expected an int or one of its members, got %s %r." % (p_class_name, p_property, p_enum.__name__ if p_enum else "int", type(p_value).__name__, p_value))
	if isinstance(p_value, str):
		key = p_value.strip().upper().replace(" ", "_")
		if p_enum is not None:
			for member in p_enum:
				if key in (member.name, getattr(member, "_full_name", member.name)):
					return int(member)
		for label, v in p_items:
			if key == label.upper().replace(" ", "_"):
				return v
		raise ValueError("%s.%s: '%s' is not one of %s." % (p_class_name, p_property, p_value, allowed))
	# Out-of-range ints go to the setter, whose error names the node too (ValueError).
	return int(p_value.__index__())


def _make_method(p_class_name, p_method, p_doc):
	name = p_method["name"]
	parameters = [_inspect.Parameter("self", _inspect.Parameter.POSITIONAL_OR_KEYWORD)]
	first_default = len(p_method["args"]) - len(p_method["defaults"])
	for i, (arg_name, arg_type) in enumerate(p_method["args"]):
		if _keyword.iskeyword(arg_name):
			arg_name += "_"  # set_global_transform(global) -> global_ (PEP 8).
		default = p_method["defaults"][i - first_default] if i >= first_default else _inspect.Parameter.empty
		parameters.append(_inspect.Parameter(arg_name, _inspect.Parameter.POSITIONAL_OR_KEYWORD, default=default, annotation=_VARIANT_TYPES.get(arg_type, arg_type)))
	signature = _inspect.Signature(parameters, return_annotation=_VARIANT_TYPES.get(p_method["return_type"], p_method["return_type"]))

	def method(self, *args, **kwargs):
		try:
			bound = signature.bind(self, *args, **kwargs)
		except TypeError as e:
			raise TypeError("%s.%s%s: %s" % (p_class_name, name, str(signature).replace("(self, ", "(").replace("(self)", "()"), e)) from None
		return self.call(name, *bound.args[1:])

	method.__name__ = name
	method.__qualname__ = p_class_name + "." + name
	method.__signature__ = signature
	method.__doc__ = p_doc
	return method


def _property_doc(p_info, p_member_doc):
	kind = p_info["type_name"]
	if p_info["type_name"] == "Object" and p_info["class_name"]:
		kind = p_info["class_name"]
	text = "%s: %s" % (p_info["name"], kind)
	if p_info["hint_string"]:
		text += "  [%s]" % p_info["hint_string"]
	if p_member_doc:
		if p_member_doc.get("default") is not None:
			text += "  (default %s)" % p_member_doc["default"]
		text += "\n" + p_member_doc["text"]
	return text


def _find_enum(p_class_name, p_info, p_enums, p_member_doc):
	"""The enum of an int property: the class reference says it (enum="Class.Enum"), else the
	enum whose snake_case name ends the property name and has as many members as its hint."""
	if p_info["type_name"] != "int" or p_info["hint"] != _HINT_ENUM:
		return None
	if p_member_doc and p_member_doc.get("enum"):
		owner, _, enum_name = p_member_doc["enum"].rpartition(".")
		for enum_class in p_enums:
			if enum_class.__name__ == enum_name:
				return enum_class
	count = len(_hint_enum_items(p_info["hint_string"]))
	best = None
	for enum_class in p_enums:
		if p_info["name"].endswith(_snake(enum_class.__name__)) and len(enum_class) in (count, count + 1):
			if best is None or len(enum_class.__name__) > len(best.__name__):
				best = enum_class
	return best


def _all_enums(p_classes, p_class_name, p_api):
	enums = []
	name = p_class_name
	while name in p_classes:
		enums.extend(getattr(p_classes[name], "_enums", {}).values())
		name = p_api[name]["parent"] if name in p_api else ""
	return enums


def _class_setattr(self, p_name, p_value):
	enum_info = type(self)._enum_properties.get(p_name)
	if enum_info is not None:
		p_value = _enum_value(self.get_class(), p_name, enum_info[0], enum_info[1], p_value)
	_object_setattr(self, p_name, p_value)


def _make_new(p_name, p_instantiable):
	def __new__(cls, **p_properties):
		if not p_instantiable:
			raise TypeError("%s is abstract: create one of its subclasses." % p_name)
		return _module.create(cls.__name__)

	def __init__(self, **p_properties):
		for key, value in p_properties.items():
			setattr(self, key, value)

	return __new__, __init__


def _build(p_module):
	global _module, _object_setattr
	_module = p_module
	_object_setattr = p_module.Object.__setattr__
	api = {c["name"]: c for c in p_module._class_api()}
	docs = _parse_docs(p_module._class_docs())
	classes = {"Object": p_module.Object, "Node": p_module.Node}

	def depth(p_name):
		d = 0
		while p_name in api and api[p_name]["parent"]:
			p_name = api[p_name]["parent"]
			d += 1
		return d

	for name in sorted(api, key=lambda n: (depth(n), n)):
		info = api[name]
		doc = docs.get(name, {})
		parent = classes.get(info["parent"], p_module.Object)
		if name in classes:
			cls = classes[name]
		else:
			new, init = _make_new(name, info["instantiable"])
			body = {"__slots__": (), "__module__": p_module.__name__, "__new__": new, "__init__": init, "__setattr__": _class_setattr}
			cls = type(name, (parent,), body)
			classes[name] = cls
		# Class reference text.
		header = "%s (inherits %s)" % (name, info["parent"] or "nothing")
		text = [header]
		if doc.get("brief"):
			text.append(doc["brief"])
		if doc.get("description"):
			text.append(doc["description"])
		if not doc:
			text.append("Engine class %s (no class reference page in doc/classes/)." % name)
		if not info["instantiable"]:
			text.append("Abstract: create one of its subclasses.")
		else:
			text.append("Create one with %s() (optionally %s(name=..., property=value, ...))." % (name, name))
		cls.__doc__ = "\n\n".join(text)
		# Enums and constants.
		groups = {}
		for constant, enum_name, value in info["constants"]:
			groups.setdefault(enum_name, []).append((constant, value))
		enums = {}
		for enum_name, members in groups.items():
			if not enum_name:
				for constant, value in members:
					setattr(cls, constant, value)
				continue
			short = _enum_short_names([c for c, _ in members])
			enum_class = _enum.IntEnum(enum_name, [(s, v) for s, (_, v) in zip(short, members)], module=p_module.__name__, qualname=name + "." + enum_name)
			for s, (full, _) in zip(short, members):
				member = enum_class[s]
				member._full_name = full
				member.__doc__ = doc.get("constants", {}).get(full) or None
				setattr(cls, full, member)
			enum_class.__doc__ = "%s.%s: %s." % (name, enum_name, ", ".join("%s = %d" % (full, v) for full, v in members))
			setattr(cls, enum_name, enum_class)
			enums[enum_name] = enum_class
		cls._enums = enums
		# Properties.
		all_enums = list(enums.values()) + _all_enums(classes, info["parent"], api)
		enum_properties = dict(getattr(parent, "_enum_properties", {}))
		for prop in info["properties"]:
			if prop["usage"] & _USAGE_GROUP_MARKERS or prop["name"] in cls.__dict__:
				continue
			member_doc = doc.get("members", {}).get(prop["name"])
			enum_class = _find_enum(name, prop, all_enums, member_doc)
			if prop["type_name"] == "int" and prop["hint"] == _HINT_ENUM:
				enum_properties[prop["name"]] = (enum_class, _hint_enum_items(prop["hint_string"]))
			setattr(cls, prop["name"], _make_property(name, prop, enum_class, _property_doc(prop, member_doc)))
		cls._enum_properties = enum_properties
		cls._properties = [p["name"] for p in info["properties"] if not p["usage"] & _USAGE_GROUP_MARKERS]
		# Methods (the hand-written ones of Object and Node, which take Python types, stay).
		methods = []
		for method in info["methods"]:
			if hasattr(cls, method["name"]):
				continue
			setattr(cls, method["name"], _make_method(name, method, doc.get("methods", {}).get(method["name"]) or "%s.%s (bound in ClassDB)." % (name, method["name"])))
			methods.append(method["name"])
		cls._methods = methods
		cls._engine_api = info
	p_module._set_class_map(classes)
	for name, cls in classes.items():
		setattr(p_module, name, cls)
	p_module.__all__ = sorted(set(getattr(p_module, "__all__", [])) | set(classes))
	return classes
