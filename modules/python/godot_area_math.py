# godot-area: the math value types of the Python module `godot_area` (modules/python).
# Embedded into the extension at build time (SConstruct) and run when the module is
# imported; nothing here is read from the source tree at run time.
#
# Vector2, Vector3, Vector4, Color, Basis and Transform3D behave like Godot's built-in
# types: component access (v.x, v[0], c.r), arithmetic (+ - * / with vectors and
# numbers, Basis * Vector3, Transform3D * Vector3 / Transform3D), the usual methods
# (length, normalized, dot, cross, lerp, inverse, ...), == with tuples and NumPy
# conversion (numpy.asarray(v)).
#
# A value read from a property is bound to it: `light.position.x = 1` writes the new
# position back through the property setter, also through nested values
# (`node.transform.origin.y += 1`). Arithmetic results, copy() and values built by
# hand are not bound to anything. See doc/scripting.md, "Value semantics".
import math as _math


class _Value:
	"""Base of the math types: the write-back link (a callable taking the new value)."""

	__slots__ = ("_owner",)

	def _init_owner(self):
		object.__setattr__(self, "_owner", None)

	def _changed(self):
		owner = self._owner
		if owner is not None:
			owner(self)

	def _bind(self, p_owner):
		object.__setattr__(self, "_owner", p_owner)
		return self

	def copy(self):
		"""An unbound copy (changing it changes nothing else)."""
		return type(self)(self)

	def __copy__(self):
		return self.copy()

	def __deepcopy__(self, p_memo):
		return self.copy()

	def __reduce__(self):
		return (type(self), tuple(self._components()))

	def __hash__(self):
		return hash((type(self).__name__,) + tuple(self._components()))


def _numbers(p_value, p_count, p_type):
	if isinstance(p_value, (int, float)) or p_value is None or isinstance(p_value, str):
		raise TypeError("%s() takes %d numbers or a sequence of %d numbers, got %r." % (p_type, p_count, p_count, p_value))
	try:
		values = [float(x) for x in p_value]
	except TypeError:
		values = [float(x) for x in list(p_value)]
	if len(values) != p_count:
		raise ValueError("%s() needs %d components, got %d." % (p_type, p_count, len(values)))
	return values


class _Vector(_Value):
	"""Shared code of Vector2, Vector3, Vector4 and Color (fixed-size float tuples)."""

	__slots__ = ("_v",)
	_names = ()

	def __init__(self, *p_args):
		self._init_owner()
		n = len(self._names)
		if len(p_args) == 0:
			values = self._default()
		elif len(p_args) == 1:
			values = _numbers(p_args[0], n, type(self).__name__)
		elif len(p_args) == n:
			values = [float(x) for x in p_args]
		else:
			values = self._from_args(p_args)
		object.__setattr__(self, "_v", values)

	def _default(self):
		return [0.0] * len(self._names)

	def _from_args(self, p_args):
		raise TypeError("%s() takes 0, 1 or %d arguments, got %d." % (type(self).__name__, len(self._names), len(p_args)))

	def _components(self):
		return self._v

	def __getattr__(self, p_name):
		names = type(self)._names
		if p_name in names:
			return self._v[names.index(p_name)]
		raise AttributeError("'%s' has no attribute '%s'." % (type(self).__name__, p_name))

	def __setattr__(self, p_name, p_value):
		names = type(self)._names
		if p_name not in names:
			raise AttributeError("'%s' has no attribute '%s' (components: %s)." % (type(self).__name__, p_name, ", ".join(names)))
		self._v[names.index(p_name)] = float(p_value)
		self._changed()

	def __len__(self):
		return len(self._v)

	def __getitem__(self, p_index):
		return self._v[p_index]

	def __setitem__(self, p_index, p_value):
		if isinstance(p_index, slice):
			values = [float(x) for x in p_value]
			new = list(self._v)
			new[p_index] = values
			if len(new) != len(self._v):
				raise ValueError("Cannot change the size of a %s." % type(self).__name__)
			self._v[:] = new
		else:
			self._v[p_index] = float(p_value)
		self._changed()

	def __iter__(self):
		return iter(list(self._v))

	def __array__(self, dtype=None, copy=None):
		import numpy

		return numpy.array(self._v, dtype=dtype if dtype is not None else numpy.float64)

	def tolist(self):
		return list(self._v)

	def __repr__(self):
		return "%s(%s)" % (type(self).__name__, ", ".join(repr(x) for x in self._v))

	def __str__(self):
		return "(%s)" % ", ".join("%g" % x for x in self._v)

	def __eq__(self, p_other):
		try:
			other = list(p_other)
		except TypeError:
			return NotImplemented
		return len(other) == len(self._v) and all(a == b for a, b in zip(self._v, other))

	def __ne__(self, p_other):
		result = self.__eq__(p_other)
		return result if result is NotImplemented else not result

	__hash__ = _Value.__hash__

	def _other(self, p_other):
		if isinstance(p_other, (int, float)):
			return [float(p_other)] * len(self._v)
		if isinstance(p_other, _Vector) and type(p_other) is not type(self):
			raise TypeError("Cannot combine %s with %s." % (type(self).__name__, type(p_other).__name__))
		return _numbers(p_other, len(self._v), type(self).__name__)

	def _make(self, p_values):
		return type(self)(p_values)

	def __add__(self, p_other):
		try:
			o = self._other(p_other)
		except (TypeError, ValueError):
			return NotImplemented
		return self._make([a + b for a, b in zip(self._v, o)])

	__radd__ = __add__

	def __sub__(self, p_other):
		try:
			o = self._other(p_other)
		except (TypeError, ValueError):
			return NotImplemented
		return self._make([a - b for a, b in zip(self._v, o)])

	def __rsub__(self, p_other):
		try:
			o = self._other(p_other)
		except (TypeError, ValueError):
			return NotImplemented
		return self._make([b - a for a, b in zip(self._v, o)])

	def __mul__(self, p_other):
		try:
			o = self._other(p_other)
		except (TypeError, ValueError):
			return NotImplemented
		return self._make([a * b for a, b in zip(self._v, o)])

	__rmul__ = __mul__

	def __truediv__(self, p_other):
		try:
			o = self._other(p_other)
		except (TypeError, ValueError):
			return NotImplemented
		return self._make([a / b for a, b in zip(self._v, o)])

	def __neg__(self):
		return self._make([-a for a in self._v])

	def __pos__(self):
		return self.copy()

	# In-place operators change the value itself (and write a bound value back), as GDScript's
	# `position += offset` does.
	def _assign(self, p_result):
		if p_result is NotImplemented:
			return NotImplemented
		self._v[:] = p_result._v
		self._changed()
		return self

	def __iadd__(self, p_other):
		return self._assign(self.__add__(p_other))

	def __isub__(self, p_other):
		return self._assign(self.__sub__(p_other))

	def __imul__(self, p_other):
		return self._assign(self.__mul__(p_other))

	def __itruediv__(self, p_other):
		return self._assign(self.__truediv__(p_other))

	def dot(self, p_other):
		return sum(a * b for a, b in zip(self._v, self._other(p_other)))

	def length_squared(self):
		return self.dot(self._v)

	def length(self):
		return _math.sqrt(self.length_squared())

	def normalized(self):
		length = self.length()
		return self._make([a / length for a in self._v]) if length > 0.0 else self._make(self._v)

	def is_normalized(self):
		return abs(self.length_squared() - 1.0) < 1e-4

	def distance_to(self, p_other):
		return (self - self._make(self._other(p_other))).length()

	def lerp(self, p_to, p_weight):
		o = self._other(p_to)
		return self._make([a + (b - a) * p_weight for a, b in zip(self._v, o)])

	def abs(self):
		return self._make([abs(a) for a in self._v])

	def is_equal_approx(self, p_other):
		return all(_math.isclose(a, b, rel_tol=1e-5, abs_tol=1e-5) for a, b in zip(self._v, self._other(p_other)))

	def is_finite(self):
		return all(_math.isfinite(a) for a in self._v)


class Vector2(_Vector):
	"""2D vector of floats (Godot's Vector2): x, y."""

	__slots__ = ()
	_names = ("x", "y")

	def angle(self):
		return _math.atan2(self._v[1], self._v[0])

	def aspect(self):
		return self._v[0] / self._v[1]


class Vector3(_Vector):
	"""3D vector of floats (Godot's Vector3): x, y, z. Vector3.UP, .FORWARD etc. are constants."""

	__slots__ = ()
	_names = ("x", "y", "z")

	def cross(self, p_other):
		a = self._v
		b = self._other(p_other)
		return Vector3(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])

	def rotated(self, p_axis, p_angle):
		return Basis.from_axis_angle(p_axis, p_angle) * self


class Vector4(_Vector):
	"""4D vector of floats (Godot's Vector4): x, y, z, w."""

	__slots__ = ()
	_names = ("x", "y", "z", "w")


class Color(_Vector):
	"""Linear RGBA color (Godot's Color): r, g, b, a (a defaults to 1)."""

	__slots__ = ()
	_names = ("r", "g", "b", "a")

	def __init__(self, *p_args):
		if len(p_args) == 1 and not isinstance(p_args[0], (Color, str)):
			try:
				values = [float(x) for x in p_args[0]]
			except TypeError:
				values = None
			if values is not None and len(values) == 3:
				p_args = tuple(values)
		if len(p_args) == 1 and isinstance(p_args[0], str):
			p_args = Color._parse_html(p_args[0])
		super().__init__(*p_args)

	def _from_args(self, p_args):
		if len(p_args) == 3:
			return [float(x) for x in p_args] + [1.0]
		return super()._from_args(p_args)

	def _default(self):
		return [0.0, 0.0, 0.0, 1.0]

	@staticmethod
	def _parse_html(p_text):
		text = p_text.lstrip("#")
		if len(text) not in (6, 8):
			raise ValueError("Color('%s'): expected '#rrggbb' or '#rrggbbaa'." % p_text)
		parts = [int(text[i : i + 2], 16) / 255.0 for i in range(0, len(text), 2)]
		return tuple(parts)

	def _other(self, p_other):
		if isinstance(p_other, (int, float)):
			return [float(p_other)] * 4
		values = [float(x) for x in p_other]
		if len(values) == 3:
			values.append(1.0)
		if len(values) != 4:
			raise ValueError("Color needs 3 or 4 components, got %d." % len(values))
		return values

	def __eq__(self, p_other):
		try:
			other = [float(x) for x in p_other]
		except TypeError:
			return NotImplemented
		if len(other) == 3:
			other.append(1.0)
		return other == self._v

	__hash__ = _Value.__hash__

	def to_html(self, p_with_alpha=True):
		parts = self._v if p_with_alpha else self._v[:3]
		return "".join("%02x" % max(0, min(255, round(c * 255.0))) for c in parts)


class _Constant:
	"""A class constant that gives a fresh value on each access (Vector3.UP.x = 5 changes nothing)."""

	def __init__(self, *p_components):
		self.components = p_components

	def __get__(self, p_instance, p_owner):
		return p_owner(*self.components)


Vector2.ZERO = _Constant(0, 0)
Vector2.ONE = _Constant(1, 1)
Vector3.ZERO = _Constant(0, 0, 0)
Vector3.ONE = _Constant(1, 1, 1)
Vector3.UP = _Constant(0, 1, 0)
Vector3.DOWN = _Constant(0, -1, 0)
Vector3.LEFT = _Constant(-1, 0, 0)
Vector3.RIGHT = _Constant(1, 0, 0)
Vector3.FORWARD = _Constant(0, 0, -1)
Vector3.BACK = _Constant(0, 0, 1)
Vector4.ZERO = _Constant(0, 0, 0, 0)
Color.WHITE = _Constant(1, 1, 1)
Color.BLACK = _Constant(0, 0, 0)


class _Axis(Vector3):
	"""A Vector3 that is a column of a Basis (writes go back into the basis)."""

	__slots__ = ()


class Basis(_Value):
	"""3x3 matrix (Godot's Basis): columns x, y, z are the local axes; b[i] is column i.
	Basis * Vector3 transforms, Basis * Basis composes. numpy.asarray(b) is the 3x3 matrix."""

	__slots__ = ("_rows",)

	def __init__(self, *p_args):
		self._init_owner()
		if len(p_args) == 0:
			rows = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
		elif len(p_args) == 1 and isinstance(p_args[0], Basis):
			rows = [list(r) for r in p_args[0]._rows]
		elif len(p_args) == 1:
			rows = [_numbers(r, 3, "Basis") for r in list(_as_list(p_args[0]))]
			if len(rows) != 3:
				raise ValueError("Basis() needs 3 rows of 3 numbers.")
		elif len(p_args) == 3:
			cols = [_numbers(c, 3, "Basis") for c in p_args]  # Godot: Basis(x_axis, y_axis, z_axis).
			rows = [[cols[j][i] for j in range(3)] for i in range(3)]
		else:
			raise TypeError("Basis() takes nothing, a 3x3 matrix, a Basis or three axis vectors.")
		object.__setattr__(self, "_rows", rows)

	def _components(self):
		return [x for r in self._rows for x in r]

	def _column(self, p_i):
		return [self._rows[0][p_i], self._rows[1][p_i], self._rows[2][p_i]]

	def _set_column(self, p_i, p_value):
		v = _numbers(p_value, 3, "Vector3")
		for r in range(3):
			self._rows[r][p_i] = v[r]

	def _axis(self, p_i):
		def write(p_axis, p_i=p_i):
			self._set_column(p_i, p_axis)
			self._changed()

		return _Axis(self._column(p_i))._bind(write)

	def __getattr__(self, p_name):
		if p_name in ("x", "y", "z"):
			return self._axis("xyz".index(p_name))
		raise AttributeError("'Basis' has no attribute '%s'." % p_name)

	def __setattr__(self, p_name, p_value):
		if p_name not in ("x", "y", "z"):
			raise AttributeError("'Basis' has no attribute '%s' (axes: x, y, z)." % p_name)
		self._set_column("xyz".index(p_name), p_value)
		self._changed()

	def __getitem__(self, p_index):
		return self._axis(range(3)[p_index])

	def __setitem__(self, p_index, p_value):
		self._set_column(range(3)[p_index], p_value)
		self._changed()

	def __len__(self):
		return 3

	def __array__(self, dtype=None, copy=None):
		import numpy

		return numpy.array(self._rows, dtype=dtype if dtype is not None else numpy.float64)

	def tolist(self):
		return [list(r) for r in self._rows]

	def __repr__(self):
		return "Basis(%s, %s, %s)" % tuple(repr(Vector3(self._column(i))) for i in range(3))

	def __eq__(self, p_other):
		if isinstance(p_other, Basis):
			return self._rows == p_other._rows
		try:
			return [list(map(float, r)) for r in _as_list(p_other)] == self._rows
		except (TypeError, ValueError):
			return NotImplemented

	__hash__ = _Value.__hash__

	def xform(self, p_vector):
		v = _numbers(p_vector, 3, "Vector3")
		return Vector3([sum(r[i] * v[i] for i in range(3)) for r in self._rows])

	def __mul__(self, p_other):
		if isinstance(p_other, Basis):
			o = p_other._rows
			return Basis([[sum(self._rows[i][k] * o[k][j] for k in range(3)) for j in range(3)] for i in range(3)])
		if isinstance(p_other, (int, float)):
			return Basis([[x * p_other for x in r] for r in self._rows])
		try:
			return self.xform(p_other)
		except (TypeError, ValueError):
			return NotImplemented

	def transposed(self):
		return Basis([self._column(i) for i in range(3)])

	def determinant(self):
		return Vector3(self._rows[0]).dot(Vector3(self._rows[1]).cross(self._rows[2]))

	def inverse(self):
		det = self.determinant()
		if det == 0.0:
			raise ValueError("Basis.inverse(): the basis is singular (determinant 0).")
		m = self._rows
		cof = [[(m[(i + 1) % 3][(j + 1) % 3] * m[(i + 2) % 3][(j + 2) % 3] - m[(i + 1) % 3][(j + 2) % 3] * m[(i + 2) % 3][(j + 1) % 3]) for j in range(3)] for i in range(3)]
		return Basis([[cof[j][i] / det for j in range(3)] for i in range(3)])

	def orthonormalized(self):
		x = Vector3(self._column(0)).normalized()
		y = Vector3(self._column(1))
		y = (y - x * x.dot(y)).normalized()
		z = Vector3(self._column(2))
		z = (z - x * x.dot(z) - y * y.dot(z)).normalized()
		return Basis(x, y, z)

	def get_scale(self):
		return Vector3(Vector3(self._column(i)).length() for i in range(3))

	def scaled(self, p_scale):
		s = _numbers(p_scale, 3, "Vector3")
		return Basis([[self._rows[i][j] * s[i] for j in range(3)] for i in range(3)])

	def rotated(self, p_axis, p_angle):
		return Basis.from_axis_angle(p_axis, p_angle) * self

	def is_equal_approx(self, p_other):
		return all(_math.isclose(a, b, rel_tol=1e-5, abs_tol=1e-5) for a, b in zip(self._components(), Basis(p_other)._components()))

	@staticmethod
	def from_axis_angle(p_axis, p_angle):
		x, y, z = Vector3(p_axis).normalized()
		c, s = _math.cos(p_angle), _math.sin(p_angle)
		t = 1.0 - c
		return Basis([[t * x * x + c, t * x * y - s * z, t * x * z + s * y], [t * x * y + s * z, t * y * y + c, t * y * z - s * x], [t * x * z - s * y, t * y * z + s * x, t * z * z + c]])

	@staticmethod
	def from_euler(p_euler):
		"""Godot's default YXZ order: Y(yaw) * X(pitch) * Z(roll), radians."""
		e = Vector3(p_euler)
		return Basis.from_axis_angle((0, 1, 0), e.y) * Basis.from_axis_angle((1, 0, 0), e.x) * Basis.from_axis_angle((0, 0, 1), e.z)

	@staticmethod
	def from_scale(p_scale):
		s = _numbers(p_scale, 3, "Vector3")
		return Basis([[s[0], 0, 0], [0, s[1], 0], [0, 0, s[2]]])

	@staticmethod
	def looking_at(p_target, p_up=(0.0, 1.0, 0.0)):
		"""-Z points along p_target (a direction), +Y towards p_up."""
		back = -Vector3(p_target).normalized()
		right = Vector3(p_up).cross(back).normalized()
		if right.length() == 0.0:
			raise ValueError("Basis.looking_at(): target and up are parallel.")
		return Basis(right, back.cross(right), back)


Basis.IDENTITY = _Constant()


def _as_list(p_value):
	if hasattr(p_value, "tolist") and not isinstance(p_value, _Value):
		return p_value.tolist()
	return list(p_value)


class Transform3D(_Value):
	"""Affine 3D transform (Godot's Transform3D): basis and origin. Transform3D * Vector3
	transforms a point; numpy.asarray(t) is the 3x4 matrix [basis | origin]; a 3x4 or 4x4
	array or nested list converts back."""

	__slots__ = ("_basis", "_origin")

	def __init__(self, *p_args):
		self._init_owner()
		if len(p_args) == 0:
			basis, origin = Basis(), [0.0, 0.0, 0.0]
		elif len(p_args) == 1 and isinstance(p_args[0], Transform3D):
			basis, origin = Basis(p_args[0]._basis), list(p_args[0]._origin)
		elif len(p_args) == 1:
			rows = _as_list(p_args[0])
			if len(rows) not in (3, 4):
				raise ValueError("Transform3D() needs a 3x4 or 4x4 matrix.")
			rows = [_numbers(r, 4, "Transform3D") for r in rows[:3]]
			basis, origin = Basis([r[:3] for r in rows]), [r[3] for r in rows]
		elif len(p_args) == 2:
			basis, origin = Basis(p_args[0]), _numbers(p_args[1], 3, "Vector3")
		elif len(p_args) == 4:
			basis, origin = Basis(*p_args[:3]), _numbers(p_args[3], 3, "Vector3")
		else:
			raise TypeError("Transform3D() takes nothing, a 3x4/4x4 matrix, (basis, origin) or (x, y, z, origin).")
		object.__setattr__(self, "_basis", basis)
		object.__setattr__(self, "_origin", origin)

	def _components(self):
		return self._basis._components() + list(self._origin)

	@property
	def basis(self):
		def write(p_basis):
			self._basis._rows[:] = [list(r) for r in p_basis._rows]
			self._changed()

		return Basis(self._basis)._bind(write)

	@property
	def origin(self):
		def write(p_origin):
			self._origin[:] = list(p_origin._v)
			self._changed()

		return Vector3(self._origin)._bind(write)

	def __setattr__(self, p_name, p_value):
		if p_name == "basis":
			object.__setattr__(self, "_basis", Basis(p_value))
		elif p_name == "origin":
			self._origin[:] = _numbers(p_value, 3, "Vector3")
		else:
			raise AttributeError("'Transform3D' has no attribute '%s' (basis, origin)." % p_name)
		self._changed()

	def tolist(self):
		return [self._basis._rows[i] + [self._origin[i]] for i in range(3)]

	def __array__(self, dtype=None, copy=None):
		import numpy

		return numpy.array(self.tolist(), dtype=dtype if dtype is not None else numpy.float64)

	def __len__(self):
		return 3

	def __getitem__(self, p_index):
		return self.tolist()[p_index]

	def __iter__(self):
		return iter(self.tolist())

	def __repr__(self):
		return "Transform3D(%r, %r)" % (self._basis, Vector3(self._origin))

	def __eq__(self, p_other):
		if isinstance(p_other, Transform3D):
			return self.tolist() == p_other.tolist()
		try:
			return Transform3D(p_other).tolist() == self.tolist()
		except (TypeError, ValueError):
			return NotImplemented

	__hash__ = _Value.__hash__

	def xform(self, p_vector):
		return self._basis.xform(p_vector) + self._origin

	def __mul__(self, p_other):
		if isinstance(p_other, Transform3D):
			return Transform3D(self._basis * p_other._basis, self.xform(p_other._origin))
		try:
			return self.xform(p_other)
		except (TypeError, ValueError):
			return NotImplemented

	def affine_inverse(self):
		inv = self._basis.inverse()
		return Transform3D(inv, -(inv * self._origin))

	def inverse(self):
		inv = self._basis.transposed()
		return Transform3D(inv, -(inv * self._origin))

	def translated(self, p_offset):
		return Transform3D(self._basis, Vector3(self._origin) + p_offset)

	def rotated(self, p_axis, p_angle):
		r = Basis.from_axis_angle(p_axis, p_angle)
		return Transform3D(r * self._basis, r * self._origin)

	def scaled(self, p_scale):
		s = Basis.from_scale(p_scale)
		return Transform3D(s * self._basis, s * self._origin)

	def looking_at(self, p_target, p_up=(0.0, 1.0, 0.0)):
		return Transform3D(Basis.looking_at(Vector3(p_target) - self._origin, p_up), self._origin)

	def orthonormalized(self):
		return Transform3D(self._basis.orthonormalized(), self._origin)

	def is_equal_approx(self, p_other):
		return all(_math.isclose(a, b, rel_tol=1e-5, abs_tol=1e-5) for a, b in zip(self._components(), Transform3D(p_other)._components()))


Transform3D.IDENTITY = _Constant()
