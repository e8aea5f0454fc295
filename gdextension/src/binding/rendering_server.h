#pragma once
// The few RenderingServer methods the extension calls, looked up by name and hash at start-up.
#include "godot_api.h"

namespace gdx {

class RenderingServer {
public:
	// Looks the methods up once; false (with an error printed) when the engine lacks one of them.
	static bool ensure_loaded();
	static void unload();

	// The instance formats the core writes (instance_buffer.h): 3D transforms with colours (the
	// dynamic buckets), with custom data too (plants drawn whole), or the compact far record as 2D
	// transforms without colours (static chunks).
	enum Format {
		TRANSFORM_AND_COLOUR,
		TRANSFORM_COLOUR_AND_CUSTOM,
		COMPACT,
	};
	static void multimesh_allocate_data(Rid p_multimesh, int64_t p_instances, Format p_format = TRANSFORM_AND_COLOUR);
	static void multimesh_set_buffer(Rid p_multimesh, const PackedFloat32Array &p_buffer);
	static void multimesh_set_visible_instances(Rid p_multimesh, int64_t p_visible);
	// The box the renderer culls the MultiMesh by (in its instance's space), instead of one it
	// would compute from every instance.
	static void multimesh_set_custom_aabb(Rid p_multimesh, const AABB &p_aabb);
};

} // namespace gdx
