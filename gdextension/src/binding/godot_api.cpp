#include "godot_api.h"

#include "api_hashes.gen.h"

#include <cstdio>

namespace gdx {

Api api;

namespace {

template <class F>
bool load(F &r_function, const char *p_name) {
	r_function = reinterpret_cast<F>(api.get_proc_address(p_name));
	if (!r_function) {
		std::fprintf(stderr, "sunflower: the engine lacks the GDExtension function '%s'\n", p_name);
		return false;
	}
	return true;
}

struct PackedMethods {
	GDExtensionPtrBuiltInMethod size = nullptr;
	GDExtensionPtrBuiltInMethod resize = nullptr;
};

PackedMethods &packed_methods(GDExtensionVariantType p_type) {
	static PackedMethods bytes, ints, longs, floats, none;
	switch (p_type) {
		case GDEXTENSION_VARIANT_TYPE_PACKED_BYTE_ARRAY:
			return bytes;
		case GDEXTENSION_VARIANT_TYPE_PACKED_INT32_ARRAY:
			return ints;
		case GDEXTENSION_VARIANT_TYPE_PACKED_INT64_ARRAY:
			return longs;
		case GDEXTENSION_VARIANT_TYPE_PACKED_FLOAT32_ARRAY:
			return floats;
		default:
			return none; // unused: PackedArray is instantiated only for the four types above
	}
}

bool load_packed_methods(GDExtensionVariantType p_type, int64_t p_size_hash, int64_t p_resize_hash) {
	StringName size_name("size");
	StringName resize_name("resize");
	PackedMethods &methods = packed_methods(p_type);
	methods.size = api.variant_get_ptr_builtin_method(p_type, size_name.ptr(), p_size_hash);
	methods.resize = api.variant_get_ptr_builtin_method(p_type, resize_name.ptr(), p_resize_hash);
	return methods.size && methods.resize;
}

} // namespace

bool load_api(GDExtensionInterfaceGetProcAddress p_get_proc_address, GDExtensionClassLibraryPtr p_library) {
	api.get_proc_address = p_get_proc_address;
	api.library = p_library;
	bool ok = true;
	ok &= load(api.get_godot_version2, "get_godot_version2");
	ok &= load(api.print_error_with_message, "print_error_with_message");
	ok &= load(api.string_name_new_with_utf8_chars, "string_name_new_with_utf8_chars");
	ok &= load(api.string_new_with_utf8_chars_and_len2, "string_new_with_utf8_chars_and_len2");
	ok &= load(api.string_to_utf8_chars, "string_to_utf8_chars");
	ok &= load(api.variant_get_ptr_constructor, "variant_get_ptr_constructor");
	ok &= load(api.variant_get_ptr_destructor, "variant_get_ptr_destructor");
	ok &= load(api.variant_get_ptr_builtin_method, "variant_get_ptr_builtin_method");
	ok &= load(api.get_variant_from_type_constructor, "get_variant_from_type_constructor");
	ok &= load(api.get_variant_to_type_constructor, "get_variant_to_type_constructor");
	ok &= load(api.variant_get_type, "variant_get_type");
	ok &= load(api.variant_can_convert_strict, "variant_can_convert_strict");
	ok &= load(api.variant_construct, "variant_construct");
	ok &= load(api.variant_destroy, "variant_destroy");
	ok &= load(api.packed_byte_array_operator_index, "packed_byte_array_operator_index");
	ok &= load(api.packed_byte_array_operator_index_const, "packed_byte_array_operator_index_const");
	ok &= load(api.packed_int32_array_operator_index, "packed_int32_array_operator_index");
	ok &= load(api.packed_int32_array_operator_index_const, "packed_int32_array_operator_index_const");
	ok &= load(api.packed_int64_array_operator_index, "packed_int64_array_operator_index");
	ok &= load(api.packed_int64_array_operator_index_const, "packed_int64_array_operator_index_const");
	ok &= load(api.packed_float32_array_operator_index, "packed_float32_array_operator_index");
	ok &= load(api.packed_float32_array_operator_index_const, "packed_float32_array_operator_index_const");
	ok &= load(api.classdb_register_extension_class5, "classdb_register_extension_class5");
	ok &= load(api.classdb_register_extension_class_method, "classdb_register_extension_class_method");
	ok &= load(api.classdb_register_extension_class_integer_constant, "classdb_register_extension_class_integer_constant");
	ok &= load(api.classdb_unregister_extension_class, "classdb_unregister_extension_class");
	ok &= load(api.classdb_construct_object2, "classdb_construct_object2");
	ok &= load(api.classdb_get_method_bind, "classdb_get_method_bind");
	ok &= load(api.object_set_instance, "object_set_instance");
	ok &= load(api.object_set_instance_binding, "object_set_instance_binding");
	ok &= load(api.object_get_instance_binding, "object_get_instance_binding");
	ok &= load(api.object_get_instance_id, "object_get_instance_id");
	ok &= load(api.object_get_instance_from_id, "object_get_instance_from_id");
	ok &= load(api.object_cast_to, "object_cast_to");
	ok &= load(api.classdb_get_class_tag, "classdb_get_class_tag");
	ok &= load(api.object_method_bind_ptrcall, "object_method_bind_ptrcall");
	ok &= load(api.global_get_singleton, "global_get_singleton");
	ok &= load(api.editor_help_load_xml_from_utf8_chars_and_len, "editor_help_load_xml_from_utf8_chars_and_len");
	if (!ok) {
		return false;
	}
	ok &= load_packed_methods(GDEXTENSION_VARIANT_TYPE_PACKED_BYTE_ARRAY, hashes::PACKED_BYTE_ARRAY_SIZE, hashes::PACKED_BYTE_ARRAY_RESIZE);
	ok &= load_packed_methods(GDEXTENSION_VARIANT_TYPE_PACKED_INT32_ARRAY, hashes::PACKED_INT32_ARRAY_SIZE, hashes::PACKED_INT32_ARRAY_RESIZE);
	ok &= load_packed_methods(GDEXTENSION_VARIANT_TYPE_PACKED_INT64_ARRAY, hashes::PACKED_INT64_ARRAY_SIZE, hashes::PACKED_INT64_ARRAY_RESIZE);
	ok &= load_packed_methods(GDEXTENSION_VARIANT_TYPE_PACKED_FLOAT32_ARRAY, hashes::PACKED_FLOAT32_ARRAY_SIZE, hashes::PACKED_FLOAT32_ARRAY_RESIZE);
	if (!ok) {
		std::fprintf(stderr, "sunflower: the engine's packed-array methods do not match the API this library was built against\n");
	}
	return ok;
}

void print_error(const std::string &p_message, const char *p_function, const char *p_file, int p_line) {
	api.print_error_with_message("Sunflower", p_message.c_str(), p_function, p_file, p_line, true);
}

std::string String::utf8() const {
	const GDExtensionInt length = api.string_to_utf8_chars(ptr(), nullptr, 0);
	std::string out(static_cast<size_t>(length), '\0');
	if (length > 0) {
		api.string_to_utf8_chars(ptr(), out.data(), length);
	}
	return out;
}

int64_t packed_size(GDExtensionVariantType p_type, GDExtensionConstTypePtr p_array) {
	int64_t size = 0;
	packed_methods(p_type).size(const_cast<GDExtensionTypePtr>(p_array), nullptr, &size, 0);
	return size;
}

void packed_resize(GDExtensionVariantType p_type, GDExtensionTypePtr p_array, int64_t p_size) {
	int64_t error = 0;
	GDExtensionConstTypePtr args[1] = { &p_size };
	packed_methods(p_type).resize(p_array, args, &error, 1);
}

template <>
void *PackedByteArray::index(GDExtensionTypePtr p_self, GDExtensionInt p_i) {
	return api.packed_byte_array_operator_index(p_self, p_i);
}
template <>
const void *PackedByteArray::index_const(GDExtensionConstTypePtr p_self, GDExtensionInt p_i) {
	return api.packed_byte_array_operator_index_const(p_self, p_i);
}
template <>
void *PackedInt32Array::index(GDExtensionTypePtr p_self, GDExtensionInt p_i) {
	return api.packed_int32_array_operator_index(p_self, p_i);
}
template <>
const void *PackedInt32Array::index_const(GDExtensionConstTypePtr p_self, GDExtensionInt p_i) {
	return api.packed_int32_array_operator_index_const(p_self, p_i);
}
template <>
void *PackedInt64Array::index(GDExtensionTypePtr p_self, GDExtensionInt p_i) {
	return api.packed_int64_array_operator_index(p_self, p_i);
}
template <>
const void *PackedInt64Array::index_const(GDExtensionConstTypePtr p_self, GDExtensionInt p_i) {
	return api.packed_int64_array_operator_index_const(p_self, p_i);
}
template <>
void *PackedFloat32Array::index(GDExtensionTypePtr p_self, GDExtensionInt p_i) {
	return api.packed_float32_array_operator_index(p_self, p_i);
}
template <>
const void *PackedFloat32Array::index_const(GDExtensionConstTypePtr p_self, GDExtensionInt p_i) {
	return api.packed_float32_array_operator_index_const(p_self, p_i);
}

} // namespace gdx
