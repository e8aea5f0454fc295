#pragma once
// Registering C++ classes and their methods with Godot's ClassDB through the C interface.
// Methods are bound from member-function pointers; both the variant call (GDScript's dynamic calls)
// and the ptrcall (typed calls) are generated from the signature.
#include "godot_api.h"

#include <initializer_list>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace gdx {

// Long-lived StringNames/Strings handed to the engine; all destroyed by release_api().
const StringName *intern_name(const char *p_name);
const String *intern_string(const char *p_text);

// --- How each argument/return type crosses the interface ----------------------------------------

template <class T>
struct Traits;

template <GDExtensionVariantType TYPE, class Storage, GDExtensionClassMethodArgumentMetadata META = GDEXTENSION_METHOD_ARGUMENT_METADATA_NONE>
struct PodTraits {
	static constexpr GDExtensionVariantType type = TYPE;
	static constexpr GDExtensionClassMethodArgumentMetadata metadata = META;
	static constexpr const char *class_name = nullptr; // an object argument's class
	using StorageType = Storage;
};

template <>
struct Traits<bool> : PodTraits<GDEXTENSION_VARIANT_TYPE_BOOL, GDExtensionBool> {
	static bool get(const GDExtensionBool &p_s) { return p_s != 0; }
	static GDExtensionBool put(bool p_v) { return p_v ? 1 : 0; }
};
template <>
struct Traits<int64_t> : PodTraits<GDEXTENSION_VARIANT_TYPE_INT, int64_t, GDEXTENSION_METHOD_ARGUMENT_METADATA_INT_IS_INT64> {
	static int64_t get(const int64_t &p_s) { return p_s; }
	static int64_t put(int64_t p_v) { return p_v; }
};
template <>
struct Traits<double> : PodTraits<GDEXTENSION_VARIANT_TYPE_FLOAT, double, GDEXTENSION_METHOD_ARGUMENT_METADATA_REAL_IS_DOUBLE> {
	static double get(const double &p_s) { return p_s; }
	static double put(double p_v) { return p_v; }
};

template <class T, GDExtensionVariantType TYPE>
struct SameTraits : PodTraits<TYPE, T> {
	static const T &get(const T &p_s) { return p_s; }
	static const T &put(const T &p_v) { return p_v; }
};
template <>
struct Traits<Vector2> : SameTraits<Vector2, GDEXTENSION_VARIANT_TYPE_VECTOR2> {};
template <>
struct Traits<Vector3> : SameTraits<Vector3, GDEXTENSION_VARIANT_TYPE_VECTOR3> {};
template <>
struct Traits<AABB> : SameTraits<AABB, GDEXTENSION_VARIANT_TYPE_AABB> {};
template <>
struct Traits<Rid> : SameTraits<Rid, GDEXTENSION_VARIANT_TYPE_RID> {};
template <>
struct Traits<String> : SameTraits<String, GDEXTENSION_VARIANT_TYPE_STRING> {};
template <>
struct Traits<PackedByteArray> : SameTraits<PackedByteArray, GDEXTENSION_VARIANT_TYPE_PACKED_BYTE_ARRAY> {};
template <>
struct Traits<PackedInt32Array> : SameTraits<PackedInt32Array, GDEXTENSION_VARIANT_TYPE_PACKED_INT32_ARRAY> {};
template <>
struct Traits<PackedInt64Array> : SameTraits<PackedInt64Array, GDEXTENSION_VARIANT_TYPE_PACKED_INT64_ARRAY> {};
template <>
struct Traits<PackedFloat32Array> : SameTraits<PackedFloat32Array, GDEXTENSION_VARIANT_TYPE_PACKED_FLOAT32_ARRAY> {};

// The instance of a class this library registers (T::CLASS, or a class inheriting it) behind an
// engine object, null when the engine object is null or of another class.
void *registered_instance(GDExtensionConstObjectPtr p_object, const char *p_class);

// An object argument of one of this library's classes: its instance (null: none given, or an object
// of another class) and its engine object's id, which stays unique after the object is freed.
template <class T>
struct Instance {
	T *instance = nullptr;
	uint64_t id = 0;
};
template <class T>
struct Traits<Instance<T>> : PodTraits<GDEXTENSION_VARIANT_TYPE_OBJECT, GDExtensionObjectPtr> {
	static constexpr const char *class_name = T::CLASS;
	static Instance<T> get(const GDExtensionObjectPtr &p_s) {
		T *instance = static_cast<T *>(registered_instance(p_s, T::CLASS));
		return Instance<T>{ instance, instance ? api.object_get_instance_id(p_s) : 0 };
	}
};

// A registered instance held by its engine object's id (Instance::id): found again at each use, so
// an object freed meanwhile is found gone (null), never dangling.
template <class T>
class Held {
public:
	Held() = default;
	explicit Held(const Instance<T> &p_instance) :
			_id(p_instance.id) {}
	T *get() const { return _id ? static_cast<T *>(registered_instance(api.object_get_instance_from_id(_id), T::CLASS)) : nullptr; }

private:
	uint64_t _id = 0;
};

template <class T>
using TraitsOf = Traits<std::remove_cv_t<std::remove_reference_t<T>>>;

// Reads a Variant argument into r_storage, converting where Godot would (int → float); false when
// the argument cannot be converted.
bool variant_to(GDExtensionVariantType p_type, GDExtensionConstVariantPtr p_variant, GDExtensionTypePtr r_storage);
void variant_from(GDExtensionVariantType p_type, GDExtensionVariantPtr r_variant, GDExtensionConstTypePtr p_value);

// --- Method binds --------------------------------------------------------------------------------

class MethodBind {
public:
	virtual ~MethodBind() = default;
	virtual void call(void *p_instance, const GDExtensionConstVariantPtr *p_args, GDExtensionInt p_count,
			GDExtensionVariantPtr r_return, GDExtensionCallError *r_error) = 0;
	virtual void ptrcall(void *p_instance, const GDExtensionConstTypePtr *p_args, GDExtensionTypePtr r_return) = 0;
};

template <class F>
struct FunctionTraits;
template <class C, class R, class... A>
struct FunctionTraits<R (C::*)(A...)> {
	using Class = C;
	using Return = R;
	using Args = std::tuple<A...>;
	static constexpr bool is_const = false;
	static constexpr bool is_static = false;
};
template <class C, class R, class... A>
struct FunctionTraits<R (C::*)(A...) const> : FunctionTraits<R (C::*)(A...)> {
	static constexpr bool is_const = true;
};
// A static method: a plain function, called without an instance.
template <class R, class... A>
struct FunctionTraits<R (*)(A...)> {
	using Class = void;
	using Return = R;
	using Args = std::tuple<A...>;
	static constexpr bool is_const = false;
	static constexpr bool is_static = true;
};

template <class F>
class MethodBindT : public MethodBind {
	using FT = FunctionTraits<F>;
	using C = typename FT::Class;
	using R = typename FT::Return;
	using Args = typename FT::Args;
	static constexpr size_t N = std::tuple_size_v<Args>;
	template <size_t I>
	using ArgTraits = TraitsOf<std::tuple_element_t<I, Args>>;

public:
	explicit MethodBindT(F p_function) :
			_function(p_function) {}

	void call(void *p_instance, const GDExtensionConstVariantPtr *p_args, GDExtensionInt p_count,
			GDExtensionVariantPtr r_return, GDExtensionCallError *r_error) override {
		if (p_count != static_cast<GDExtensionInt>(N)) {
			r_error->error = p_count < static_cast<GDExtensionInt>(N) ? GDEXTENSION_CALL_ERROR_TOO_FEW_ARGUMENTS : GDEXTENSION_CALL_ERROR_TOO_MANY_ARGUMENTS;
			r_error->expected = static_cast<int32_t>(N);
			return;
		}
		call_variant(p_instance, p_args, r_return, r_error, std::make_index_sequence<N>{});
	}

	void ptrcall(void *p_instance, const GDExtensionConstTypePtr *p_args, GDExtensionTypePtr r_return) override {
		call_ptr(p_instance, p_args, r_return, std::make_index_sequence<N>{});
	}

private:
	template <class... P>
	R invoke(void *p_instance, P &&...p_args) {
		if constexpr (FT::is_static) {
			return _function(std::forward<P>(p_args)...);
		} else {
			return (static_cast<C *>(p_instance)->*_function)(std::forward<P>(p_args)...);
		}
	}

	template <size_t... I>
	void call_variant(void *p_self, const GDExtensionConstVariantPtr *p_args, GDExtensionVariantPtr r_return,
			GDExtensionCallError *r_error, std::index_sequence<I...>) {
		std::tuple<typename ArgTraits<I>::StorageType...> storage;
		int32_t failed = -1;
		const auto read = [&](size_t p_index, GDExtensionVariantType p_type, GDExtensionTypePtr r_slot) {
			if (failed < 0 && !variant_to(p_type, p_args[p_index], r_slot)) {
				failed = static_cast<int32_t>(p_index);
				r_error->expected = p_type;
			}
		};
		(read(I, ArgTraits<I>::type, &std::get<I>(storage)), ...);
		(void)read; // unused for methods without arguments
		if (failed >= 0) {
			r_error->error = GDEXTENSION_CALL_ERROR_INVALID_ARGUMENT;
			r_error->argument = failed;
			return;
		}
		if constexpr (std::is_void_v<R>) {
			invoke(p_self, ArgTraits<I>::get(std::get<I>(storage))...);
		} else {
			using RT = TraitsOf<R>;
			const typename RT::StorageType result = RT::put(invoke(p_self, ArgTraits<I>::get(std::get<I>(storage))...));
			variant_from(RT::type, r_return, &result);
		}
	}

	template <size_t... I>
	void call_ptr(void *p_self, const GDExtensionConstTypePtr *p_args, GDExtensionTypePtr r_return, std::index_sequence<I...>) {
		if constexpr (std::is_void_v<R>) {
			invoke(p_self, ArgTraits<I>::get(*static_cast<const typename ArgTraits<I>::StorageType *>(p_args[I]))...);
		} else {
			using RT = TraitsOf<R>;
			// The return slot is already constructed: assign into it.
			*static_cast<typename RT::StorageType *>(r_return) =
					RT::put(invoke(p_self, ArgTraits<I>::get(*static_cast<const typename ArgTraits<I>::StorageType *>(p_args[I]))...));
		}
	}

	F _function;
};

// --- Class registration ---------------------------------------------------------------------------

struct ArgumentInfo {
	GDExtensionVariantType type;
	GDExtensionClassMethodArgumentMetadata metadata;
	const char *class_name; // an object's class, or null
};

void register_method(const char *p_class, const char *p_name, MethodBind *p_bind, bool p_const, bool p_static,
		bool p_has_return, ArgumentInfo p_return, const std::vector<ArgumentInfo> &p_args,
		std::initializer_list<const char *> p_arg_names);

template <class Args, size_t... I>
std::vector<ArgumentInfo> argument_infos(std::index_sequence<I...>) {
	return { ArgumentInfo{ TraitsOf<std::tuple_element_t<I, Args>>::type, TraitsOf<std::tuple_element_t<I, Args>>::metadata,
			TraitsOf<std::tuple_element_t<I, Args>>::class_name }... };
}

template <class F>
void bind_method(const char *p_class, const char *p_name, F p_function, std::initializer_list<const char *> p_arg_names = {}) {
	using FT = FunctionTraits<F>;
	using R = typename FT::Return;
	const std::vector<ArgumentInfo> args = argument_infos<typename FT::Args>(std::make_index_sequence<std::tuple_size_v<typename FT::Args>>{});
	ArgumentInfo ret{ GDEXTENSION_VARIANT_TYPE_NIL, GDEXTENSION_METHOD_ARGUMENT_METADATA_NONE, nullptr };
	if constexpr (!std::is_void_v<R>) {
		ret = ArgumentInfo{ TraitsOf<R>::type, TraitsOf<R>::metadata, TraitsOf<R>::class_name };
	}
	register_method(p_class, p_name, new MethodBindT<F>(p_function), FT::is_const, FT::is_static, !std::is_void_v<R>, ret,
			args, p_arg_names);
}

void bind_integer_constant(const char *p_class, const char *p_enum, const char *p_name, int64_t p_value);

// Registers T (default-constructible, named T::CLASS; the engine object that wraps it is not kept)
// as a subclass of p_parent, then calls T::bind_methods().
struct ClassInfo {
	const char *utf8_name; // (static storage)
	const StringName *name;
	const StringName *parent;
	void *(*create)();
	void (*destroy)(void *);
};
void register_class(const ClassInfo &p_info);
void unregister_classes();

template <class T>
void register_class(const char *p_parent) {
	register_class(ClassInfo{ T::CLASS, intern_name(T::CLASS), intern_name(p_parent),
			[]() -> void * { return new T(); },
			[](void *p_instance) { delete static_cast<T *>(p_instance); } });
	T::bind_methods();
}

} // namespace gdx
