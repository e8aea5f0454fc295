#pragma once
// The few RenderingServer methods the extension calls, looked up by name and hash at start-up.
#include "godot_api.h"

namespace gdx {

class RenderingServer {
public:
	// Looks the methods up once; false (with an error printed) when the engine lacks one of them.
	static bool ensure_loaded();
	static void unload();

	static void multimesh_allocate_data(Rid p_multimesh, int64_t p_instances);
	static void multimesh_set_buffer(Rid p_multimesh, const PackedFloat32Array &p_buffer);
	static void multimesh_set_visible_instances(Rid p_multimesh, int64_t p_visible);
};

} // namespace gdx
