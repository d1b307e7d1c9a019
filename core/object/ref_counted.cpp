/**************************************************************************/
/*  ref_counted.cpp                                                       */
/**************************************************************************/

#include "core/object/ref_counted.h"

#include "core/object/class_db.h"

void RefCounted::_bind_methods() {
	ClassDB::bind_method(D_METHOD("get_reference_count"), &RefCounted::get_reference_count);
}

bool RefCounted::reference() {
	refcount.fetch_add(1);
	return true;
}

bool RefCounted::unreference() {
	return refcount.fetch_sub(1) == 1;
}

RefCounted::RefCounted() {
	_is_ref_counted = true;
}
