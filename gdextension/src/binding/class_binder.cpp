#include "class_binder.h"

#include <cstring>
#include <deque>
#include <memory>

namespace gdx {

namespace {

// Everything handed to the engine by pointer lives here until release_api().
struct Registry {
	std::deque<StringName> names;
	std::deque<String> strings;
	std::vector<std::unique_ptr<MethodBind>> methods;
	std::deque<ClassInfo> classes;
	const StringName *empty_name = nullptr;
	const String *empty_string = nullptr;
};

Registry *registry() {
	static Registry *instance = new Registry();
	return instance;
}

GDExtensionPropertyInfo property_info(GDExtensionVariantType p_type, const char *p_name, const char *p_class = nullptr) {
	Registry *reg = registry();
	if (!reg->empty_name) { // one empty class name and hint string serve every property
		reg->empty_name = intern_name("");
		reg->empty_string = intern_string("");
	}
	GDExtensionPropertyInfo info{};
	info.type = p_type;
	info.name = const_cast<StringName *>(intern_name(p_name))->ptr();
	info.class_name = const_cast<StringName *>(p_class ? intern_name(p_class) : reg->empty_name)->ptr();
	info.hint = 0; // PROPERTY_HINT_NONE
	info.hint_string = const_cast<String *>(reg->empty_string)->ptr();
	info.usage = 6; // PROPERTY_USAGE_DEFAULT
	return info;
}

void call_trampoline(void *p_method, GDExtensionClassInstancePtr p_instance, const GDExtensionConstVariantPtr *p_args,
		GDExtensionInt p_count, GDExtensionVariantPtr r_return, GDExtensionCallError *r_error) {
	r_error->error = GDEXTENSION_CALL_OK;
	static_cast<MethodBind *>(p_method)->call(p_instance, p_args, p_count, r_return, r_error);
}

void ptrcall_trampoline(void *p_method, GDExtensionClassInstancePtr p_instance, const GDExtensionConstTypePtr *p_args,
		GDExtensionTypePtr r_return) {
	static_cast<MethodBind *>(p_method)->ptrcall(p_instance, p_args, r_return);
}

// What an engine object of one of our classes carries as its instance binding (our library's
// token): its class and its instance, so that an object argument is known for what it is.
struct Bound {
	const ClassInfo *info;
	void *instance;
};

void *no_binding_made(void *, void *) {
	return nullptr; // (only our own objects have one, set when they are made)
}

void free_bound(void *, void *, void *p_binding) {
	delete static_cast<Bound *>(p_binding);
}

GDExtensionBool bound_may_die(void *, void *, GDExtensionBool) {
	return true; // the binding keeps no reference of its own
}

const GDExtensionInstanceBindingCallbacks BOUND_CALLBACKS = { &no_binding_made, &free_bound, &bound_may_die };

GDExtensionObjectPtr create_instance(void *p_class, GDExtensionBool /*p_notify_postinitialize*/) {
	const ClassInfo *info = static_cast<const ClassInfo *>(p_class);
	GDExtensionObjectPtr object = api.classdb_construct_object2(info->parent->ptr());
	void *instance = info->create();
	api.object_set_instance(object, info->name->ptr(), instance);
	api.object_set_instance_binding(object, api.library, new Bound{ info, instance }, &BOUND_CALLBACKS);
	return object;
}

void free_instance(void *p_class, GDExtensionClassInstancePtr p_instance) {
	static_cast<const ClassInfo *>(p_class)->destroy(p_instance);
}

} // namespace

const StringName *intern_name(const char *p_name) {
	return &registry()->names.emplace_back(p_name);
}

const String *intern_string(const char *p_text) {
	return &registry()->strings.emplace_back(p_text);
}

void *registered_instance(GDExtensionConstObjectPtr p_object, const char *p_class) {
	if (!p_object) {
		return nullptr;
	}
	// (Without callbacks the engine makes no binding: an object of another library's or the engine's
	// class has none of ours.)
	const Bound *bound = static_cast<const Bound *>(
			api.object_get_instance_binding(const_cast<GDExtensionObjectPtr>(p_object), api.library, nullptr));
	return bound && std::strcmp(bound->info->utf8_name, p_class) == 0 ? bound->instance : nullptr;
}

bool variant_to(GDExtensionVariantType p_type, GDExtensionConstVariantPtr p_variant, GDExtensionTypePtr r_storage) {
	const GDExtensionVariantType actual = api.variant_get_type(p_variant);
	GDExtensionTypeFromVariantConstructorFunc convert = api.get_variant_to_type_constructor(p_type);
	if (actual == p_type) {
		convert(r_storage, const_cast<GDExtensionVariantPtr>(p_variant));
		return true;
	}
	if (!api.variant_can_convert_strict(actual, p_type)) {
		return false;
	}
	alignas(8) uint8_t converted[24];
	GDExtensionCallError error{};
	GDExtensionConstVariantPtr args[1] = { p_variant };
	api.variant_construct(p_type, converted, args, 1, &error);
	if (error.error != GDEXTENSION_CALL_OK) {
		return false;
	}
	convert(r_storage, converted);
	api.variant_destroy(converted);
	return true;
}

void variant_from(GDExtensionVariantType p_type, GDExtensionVariantPtr r_variant, GDExtensionConstTypePtr p_value) {
	api.get_variant_from_type_constructor(p_type)(r_variant, const_cast<GDExtensionTypePtr>(p_value));
}

void register_method(const char *p_class, const char *p_name, MethodBind *p_bind, bool p_const, bool p_static, bool p_has_return,
		ArgumentInfo p_return, const std::vector<ArgumentInfo> &p_args, std::initializer_list<const char *> p_arg_names) {
	registry()->methods.emplace_back(p_bind);
	std::vector<GDExtensionPropertyInfo> arg_info;
	std::vector<GDExtensionClassMethodArgumentMetadata> arg_meta;
	auto name = p_arg_names.begin();
	for (size_t i = 0; i < p_args.size(); ++i) {
		const std::string fallback = "arg" + std::to_string(i);
		arg_info.push_back(property_info(p_args[i].type, name != p_arg_names.end() ? *name++ : fallback.c_str(), p_args[i].class_name));
		arg_meta.push_back(p_args[i].metadata);
	}
	GDExtensionPropertyInfo return_info = property_info(p_return.type, "");

	GDExtensionClassMethodInfo info{};
	info.name = const_cast<StringName *>(intern_name(p_name))->ptr();
	info.method_userdata = p_bind;
	info.call_func = &call_trampoline;
	info.ptrcall_func = &ptrcall_trampoline;
	info.method_flags = GDEXTENSION_METHOD_FLAGS_DEFAULT | (p_const ? GDEXTENSION_METHOD_FLAG_CONST : 0) |
			(p_static ? GDEXTENSION_METHOD_FLAG_STATIC : 0);
	info.has_return_value = p_has_return;
	info.return_value_info = p_has_return ? &return_info : nullptr;
	info.return_value_metadata = p_return.metadata;
	info.argument_count = static_cast<uint32_t>(p_args.size());
	info.arguments_info = arg_info.data();
	info.arguments_metadata = arg_meta.data();
	api.classdb_register_extension_class_method(api.library, intern_name(p_class)->ptr(), &info);
}

void bind_integer_constant(const char *p_class, const char *p_enum, const char *p_name, int64_t p_value) {
	api.classdb_register_extension_class_integer_constant(api.library, intern_name(p_class)->ptr(),
			intern_name(p_enum)->ptr(), intern_name(p_name)->ptr(), p_value, false);
}

void register_class(const ClassInfo &p_info) {
	// The class userdata must outlive the class: the registry's deque keeps its address stable.
	ClassInfo *stable = &registry()->classes.emplace_back(p_info);
	GDExtensionClassCreationInfo5 info{};
	info.is_exposed = true;
	info.create_instance_func = &create_instance;
	info.free_instance_func = &free_instance;
	info.class_userdata = stable;
	api.classdb_register_extension_class5(api.library, p_info.name->ptr(), p_info.parent->ptr(), &info);
}

void unregister_classes() {
	Registry *reg = registry();
	for (auto it = reg->classes.rbegin(); it != reg->classes.rend(); ++it) {
		api.classdb_unregister_extension_class(api.library, it->name->ptr());
	}
	reg->classes.clear();
}

void release_api() {
	Registry *reg = registry();
	reg->methods.clear();
	reg->names.clear();
	reg->strings.clear();
	reg->empty_name = nullptr;
	reg->empty_string = nullptr;
}

} // namespace gdx
