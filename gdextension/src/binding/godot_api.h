#pragma once
// A small binding on Godot's GDExtension C interface (godot-cpp is not used; see README).
// This file: the interface functions we call, and the few builtin types we pass across.
#include <gdextension_interface.h>

#include <cstdint>
#include <cstring>
#include <string>

namespace gdx {

struct Api {
	GDExtensionInterfaceGetProcAddress get_proc_address = nullptr;
	GDExtensionClassLibraryPtr library = nullptr;

	GDExtensionInterfaceGetGodotVersion2 get_godot_version2 = nullptr;
	GDExtensionInterfacePrintErrorWithMessage print_error_with_message = nullptr;
	GDExtensionInterfaceStringNameNewWithUtf8Chars string_name_new_with_utf8_chars = nullptr;
	GDExtensionInterfaceStringNewWithUtf8CharsAndLen2 string_new_with_utf8_chars_and_len2 = nullptr;
	GDExtensionInterfaceStringToUtf8Chars string_to_utf8_chars = nullptr;
	GDExtensionInterfaceVariantGetPtrConstructor variant_get_ptr_constructor = nullptr;
	GDExtensionInterfaceVariantGetPtrDestructor variant_get_ptr_destructor = nullptr;
	GDExtensionInterfaceVariantGetPtrBuiltinMethod variant_get_ptr_builtin_method = nullptr;
	GDExtensionInterfaceGetVariantFromTypeConstructor get_variant_from_type_constructor = nullptr;
	GDExtensionInterfaceGetVariantToTypeConstructor get_variant_to_type_constructor = nullptr;
	GDExtensionInterfaceVariantGetType variant_get_type = nullptr;
	GDExtensionInterfaceVariantCanConvertStrict variant_can_convert_strict = nullptr;
	GDExtensionInterfaceVariantConstruct variant_construct = nullptr;
	GDExtensionInterfaceVariantDestroy variant_destroy = nullptr;
	GDExtensionInterfacePackedByteArrayOperatorIndex packed_byte_array_operator_index = nullptr;
	GDExtensionInterfacePackedByteArrayOperatorIndexConst packed_byte_array_operator_index_const = nullptr;
	GDExtensionInterfacePackedInt32ArrayOperatorIndex packed_int32_array_operator_index = nullptr;
	GDExtensionInterfacePackedInt32ArrayOperatorIndexConst packed_int32_array_operator_index_const = nullptr;
	GDExtensionInterfacePackedInt64ArrayOperatorIndex packed_int64_array_operator_index = nullptr;
	GDExtensionInterfacePackedInt64ArrayOperatorIndexConst packed_int64_array_operator_index_const = nullptr;
	GDExtensionInterfacePackedFloat32ArrayOperatorIndex packed_float32_array_operator_index = nullptr;
	GDExtensionInterfacePackedFloat32ArrayOperatorIndexConst packed_float32_array_operator_index_const = nullptr;
	GDExtensionInterfaceClassdbRegisterExtensionClass5 classdb_register_extension_class5 = nullptr;
	GDExtensionInterfaceClassdbRegisterExtensionClassMethod classdb_register_extension_class_method = nullptr;
	GDExtensionInterfaceClassdbRegisterExtensionClassIntegerConstant classdb_register_extension_class_integer_constant = nullptr;
	GDExtensionInterfaceClassdbUnregisterExtensionClass classdb_unregister_extension_class = nullptr;
	GDExtensionInterfaceClassdbConstructObject2 classdb_construct_object2 = nullptr;
	GDExtensionInterfaceClassdbGetMethodBind classdb_get_method_bind = nullptr;
	GDExtensionInterfaceObjectSetInstance object_set_instance = nullptr;
	GDExtensionInterfaceObjectSetInstanceBinding object_set_instance_binding = nullptr;
	GDExtensionInterfaceObjectGetInstanceBinding object_get_instance_binding = nullptr;
	GDExtensionInterfaceObjectGetInstanceId object_get_instance_id = nullptr;
	GDExtensionInterfaceObjectGetInstanceFromId object_get_instance_from_id = nullptr;
	GDExtensionInterfaceObjectCastTo object_cast_to = nullptr;
	GDExtensionInterfaceClassdbGetClassTag classdb_get_class_tag = nullptr;
	GDExtensionInterfaceObjectMethodBindPtrcall object_method_bind_ptrcall = nullptr;
	GDExtensionInterfaceGlobalGetSingleton global_get_singleton = nullptr;
	GDExtensionsInterfaceEditorHelpLoadXmlFromUtf8CharsAndLen editor_help_load_xml_from_utf8_chars_and_len = nullptr;
};

extern Api api;

// Looks up every interface function; false (with a message on stderr) if one is missing.
bool load_api(GDExtensionInterfaceGetProcAddress p_get_proc_address, GDExtensionClassLibraryPtr p_library);
// Frees everything the binding interned (StringNames, Strings, method binds). Call at deinitialize.
void release_api();

void print_error(const std::string &p_message, const char *p_function, const char *p_file, int p_line);

// --- Builtin types -----------------------------------------------------------------------------

struct Vector2 {
	float x = 0.0f, y = 0.0f;
};
struct Vector3 {
	float x = 0.0f, y = 0.0f, z = 0.0f;
};
struct AABB {
	Vector3 position, size;
};
struct Rid {
	uint64_t id = 0;
	bool is_valid() const { return id != 0; }
};
static_assert(sizeof(Vector2) == 8 && sizeof(Vector3) == 12 && sizeof(AABB) == 24 && sizeof(Rid) == 8);

// An engine-owned builtin (String, StringName, Packed*Array) held by value: constructed, copied and
// destroyed through the engine's own functions.
template <GDExtensionVariantType TYPE, size_t SIZE>
class Builtin {
public:
	static constexpr GDExtensionVariantType VARIANT_TYPE = TYPE;
	Builtin() { constructor(0)(ptr(), nullptr); }
	Builtin(const Builtin &p_other) { copy_from(p_other); }
	~Builtin() { destructor()(ptr()); }
	Builtin &operator=(const Builtin &p_other) {
		if (this != &p_other) {
			destructor()(ptr());
			copy_from(p_other);
		}
		return *this;
	}
	GDExtensionTypePtr ptr() { return _opaque; }
	GDExtensionConstTypePtr ptr() const { return _opaque; }

protected:
	struct Uninitialized {};
	explicit Builtin(Uninitialized) {}
	static GDExtensionPtrConstructor constructor(int32_t p_index) {
		static GDExtensionPtrConstructor ctors[2] = { api.variant_get_ptr_constructor(TYPE, 0), api.variant_get_ptr_constructor(TYPE, 1) };
		return ctors[p_index];
	}
	static GDExtensionPtrDestructor destructor() {
		static GDExtensionPtrDestructor dtor = api.variant_get_ptr_destructor(TYPE);
		return dtor;
	}

private:
	void copy_from(const Builtin &p_other) {
		GDExtensionConstTypePtr args[1] = { p_other.ptr() };
		constructor(1)(ptr(), args);
	}
	alignas(8) uint8_t _opaque[SIZE];
};

class String : public Builtin<GDEXTENSION_VARIANT_TYPE_STRING, 8> {
public:
	String() = default;
	String(const char *p_utf8) :
			String(std::string(p_utf8)) {}
	String(const std::string &p_utf8) :
			Builtin(Uninitialized{}) {
		api.string_new_with_utf8_chars_and_len2(ptr(), p_utf8.data(), static_cast<GDExtensionInt>(p_utf8.size()));
	}
	std::string utf8() const;
};

class StringName : public Builtin<GDEXTENSION_VARIANT_TYPE_STRING_NAME, 8> {
public:
	StringName() = default;
	StringName(const char *p_utf8) :
			Builtin(Uninitialized{}) { api.string_name_new_with_utf8_chars(ptr(), p_utf8); }
};

// Size and resize of the packed arrays, through the engine's builtin methods (looked up by the hashes
// of the API dump at load time).
int64_t packed_size(GDExtensionVariantType p_type, GDExtensionConstTypePtr p_array);
void packed_resize(GDExtensionVariantType p_type, GDExtensionTypePtr p_array, int64_t p_size);

template <GDExtensionVariantType TYPE, class T>
class PackedArray : public Builtin<TYPE, 16> {
public:
	int64_t size() const { return packed_size(TYPE, this->ptr()); }
	void resize(int64_t p_size) { packed_resize(TYPE, this->ptr(), p_size); }
	// Pointer to the first element (copy-on-write is resolved first); null when empty.
	T *data() { return size() ? static_cast<T *>(index(this->ptr(), 0)) : nullptr; }
	const T *data() const { return size() ? static_cast<const T *>(index_const(this->ptr(), 0)) : nullptr; }
	void assign(const T *p_values, size_t p_count) {
		resize(static_cast<int64_t>(p_count));
		if (p_count) {
			std::memcpy(data(), p_values, p_count * sizeof(T));
		}
	}

private:
	static void *index(GDExtensionTypePtr p_self, GDExtensionInt p_i);
	static const void *index_const(GDExtensionConstTypePtr p_self, GDExtensionInt p_i);
};

using PackedByteArray = PackedArray<GDEXTENSION_VARIANT_TYPE_PACKED_BYTE_ARRAY, uint8_t>;
using PackedInt32Array = PackedArray<GDEXTENSION_VARIANT_TYPE_PACKED_INT32_ARRAY, int32_t>;
using PackedInt64Array = PackedArray<GDEXTENSION_VARIANT_TYPE_PACKED_INT64_ARRAY, int64_t>;
using PackedFloat32Array = PackedArray<GDEXTENSION_VARIANT_TYPE_PACKED_FLOAT32_ARRAY, float>;

// The element accessors are defined once, in godot_api.cpp.
template <> void *PackedByteArray::index(GDExtensionTypePtr p_self, GDExtensionInt p_i);
template <> const void *PackedByteArray::index_const(GDExtensionConstTypePtr p_self, GDExtensionInt p_i);
template <> void *PackedInt32Array::index(GDExtensionTypePtr p_self, GDExtensionInt p_i);
template <> const void *PackedInt32Array::index_const(GDExtensionConstTypePtr p_self, GDExtensionInt p_i);
template <> void *PackedInt64Array::index(GDExtensionTypePtr p_self, GDExtensionInt p_i);
template <> const void *PackedInt64Array::index_const(GDExtensionConstTypePtr p_self, GDExtensionInt p_i);
template <> void *PackedFloat32Array::index(GDExtensionTypePtr p_self, GDExtensionInt p_i);
template <> const void *PackedFloat32Array::index_const(GDExtensionConstTypePtr p_self, GDExtensionInt p_i);

} // namespace gdx
