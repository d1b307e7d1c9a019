/**************************************************************************/
/*  missing_node.cpp                                                      */
/**************************************************************************/

#include "scene/main/missing_node.h"

void MissingNode::_bind_methods() {
	ClassDB::bind_method(D_METHOD("set_original_class", "name"), &MissingNode::set_original_class);
	ClassDB::bind_method(D_METHOD("get_original_class"), &MissingNode::get_original_class);
	// Not saved as a property: the saver writes it as the node's type.
	ADD_PROPERTY(PropertyInfo(Variant::STRING, "original_class", PROPERTY_HINT_NONE, "", PROPERTY_USAGE_EDITOR | PROPERTY_USAGE_READ_ONLY), "set_original_class", "get_original_class");
}
