/**************************************************************************/
/*  ref_counted.h                                                         */
/**************************************************************************/
/* Intrusive reference counting. A RefCounted starts at count 0; the      */
/* first Ref<T> (or Variant) that holds it takes it to 1, and the last    */
/* one to let go deletes it.                                              */

#pragma once

#include "core/object/object.h"

#include <atomic>

class RefCounted : public Object {
	GDCLASS(RefCounted, Object);

	std::atomic<int> refcount{ 0 };

protected:
	static void _bind_methods();

public:
	// Takes one reference. Always true here (kept for Godot's shape).
	bool reference();
	// Drops one reference; true when it reached zero (the caller then deletes).
	bool unreference();
	int get_reference_count() const { return refcount.load(); }

	RefCounted();
	~RefCounted() override {}
};

template <class T>
class Ref {
	T *reference = nullptr;

	void _ref(T *p_ptr) {
		if (p_ptr == reference) {
			return;
		}
		unref();
		if (p_ptr) {
			p_ptr->reference();
		}
		reference = p_ptr;
	}

public:
	T *ptr() const { return reference; }
	T *operator->() const { return reference; }
	T &operator*() const { return *reference; }
	bool is_valid() const { return reference != nullptr; }
	bool is_null() const { return reference == nullptr; }

	bool operator==(const T *p_ptr) const { return reference == p_ptr; }
	bool operator!=(const T *p_ptr) const { return reference != p_ptr; }
	bool operator==(const Ref<T> &p_ref) const { return reference == p_ref.reference; }
	bool operator!=(const Ref<T> &p_ref) const { return reference != p_ref.reference; }
	bool operator<(const Ref<T> &p_ref) const { return reference < p_ref.reference; }

	void unref() {
		if (reference && reference->unreference()) {
			delete reference;
		}
		reference = nullptr;
	}

	// Creates a new T and holds it.
	template <class... A>
	void instantiate(A &&...p_args) {
		_ref(new T(std::forward<A>(p_args)...));
	}

	Ref &operator=(const Ref &p_ref) {
		_ref(p_ref.reference);
		return *this;
	}
	template <class U>
	Ref &operator=(const Ref<U> &p_ref) {
		_ref(dynamic_cast<T *>(p_ref.ptr()));
		return *this;
	}

	Ref() {}
	Ref(T *p_ptr) { _ref(p_ptr); }
	Ref(const Ref &p_ref) { _ref(p_ref.reference); }
	Ref(Ref &&p_ref) {
		reference = p_ref.reference;
		p_ref.reference = nullptr;
	}
	// Cross-type: null when the held object is not a T.
	template <class U>
	Ref(const Ref<U> &p_ref) { _ref(dynamic_cast<T *>(p_ref.ptr())); }
	// From a Variant holding an object of class T (null otherwise).
	Ref(const Variant &p_variant) { _ref(dynamic_cast<T *>(p_variant.get_object())); }

	operator Variant() const { return Variant((const Object *)reference); }

	~Ref() { unref(); }
};

template <class T>
struct VariantCaster<Ref<T>> {
	static constexpr Variant::Type TYPE = Variant::OBJECT;
	static bool check(const Variant &p_v) {
		if (p_v.get_type() == Variant::NIL) {
			return true;
		}
		return p_v.get_type() == Variant::OBJECT && (p_v.get_object() == nullptr || dynamic_cast<T *>(p_v.get_object()) != nullptr);
	}
	static Ref<T> cast(const Variant &p_v) { return Ref<T>(dynamic_cast<T *>(p_v.get_object())); }
	static Variant to_variant(const Ref<T> &p_value) { return Variant((const Object *)p_value.ptr()); }
};
