#include "rendering_server.h"

#include "api_hashes.gen.h"
#include "error_macros.h"

namespace gdx {

namespace {

struct Methods {
	GDExtensionObjectPtr singleton = nullptr;
	GDExtensionMethodBindPtr allocate_data = nullptr;
	GDExtensionMethodBindPtr set_buffer = nullptr;
	GDExtensionMethodBindPtr set_visible_instances = nullptr;
	GDExtensionMethodBindPtr set_custom_aabb = nullptr;
};
Methods methods;

void call(GDExtensionMethodBindPtr p_method, std::initializer_list<GDExtensionConstTypePtr> p_args) {
	SF_BUG_COND_MSG(methods.singleton == nullptr || p_method == nullptr, "a RenderingServer call before ensure_loaded() succeeded");
	api.object_method_bind_ptrcall(p_method, methods.singleton, p_args.begin(), nullptr);
}

} // namespace

bool RenderingServer::ensure_loaded() {
	if (methods.singleton) {
		return methods.allocate_data && methods.set_buffer && methods.set_visible_instances && methods.set_custom_aabb;
	}
	StringName class_name("RenderingServer");
	methods.singleton = api.global_get_singleton(class_name.ptr());
	const auto bind = [&](const char *p_name, int64_t p_hash) {
		StringName name(p_name);
		GDExtensionMethodBindPtr method = api.classdb_get_method_bind(class_name.ptr(), name.ptr(), p_hash);
		SF_FAIL_COND_V_MSG(method == nullptr, method,
				std::string("this engine's RenderingServer.") + p_name + " differs from the one the library was built against");
		return method;
	};
	methods.allocate_data = bind("multimesh_allocate_data", hashes::RS_MULTIMESH_ALLOCATE_DATA);
	methods.set_buffer = bind("multimesh_set_buffer", hashes::RS_MULTIMESH_SET_BUFFER);
	methods.set_visible_instances = bind("multimesh_set_visible_instances", hashes::RS_MULTIMESH_SET_VISIBLE_INSTANCES);
	methods.set_custom_aabb = bind("multimesh_set_custom_aabb", hashes::RS_MULTIMESH_SET_CUSTOM_AABB);
	return methods.singleton && methods.allocate_data && methods.set_buffer && methods.set_visible_instances &&
			methods.set_custom_aabb;
}

void RenderingServer::unload() {
	methods = Methods{};
}

void RenderingServer::multimesh_allocate_data(Rid p_multimesh, int64_t p_instances, Format p_format) {
	// RenderingServer.MULTIMESH_TRANSFORM_2D is 0, MULTIMESH_TRANSFORM_3D 1.
	const int64_t transform = p_format == COMPACT ? 0 : 1;
	const GDExtensionBool colours = p_format == COMPACT ? 0 : 1;
	const GDExtensionBool custom = p_format == TRANSFORM_COLOUR_AND_CUSTOM ? 1 : 0;
	const GDExtensionBool no = 0;
	call(methods.allocate_data, { &p_multimesh, &p_instances, &transform, &colours, &custom, &no });
}

void RenderingServer::multimesh_set_buffer(Rid p_multimesh, const PackedFloat32Array &p_buffer) {
	call(methods.set_buffer, { &p_multimesh, p_buffer.ptr() });
}

void RenderingServer::multimesh_set_visible_instances(Rid p_multimesh, int64_t p_visible) {
	call(methods.set_visible_instances, { &p_multimesh, &p_visible });
}

void RenderingServer::multimesh_set_custom_aabb(Rid p_multimesh, const AABB &p_aabb) {
	call(methods.set_custom_aabb, { &p_multimesh, &p_aabb });
}

} // namespace gdx
