#pragma once
// A plant type's form: how its three parts stack and the space it takes, in model units (a part's
// root at its origin, its height along +y), and the metres per model unit it is drawn at. The
// addon's plant resource (SunflowerPlant) sets every value; the defaults are the built-in sunflower.
#include "parameters.h"

#include <glm/vec3.hpp>

namespace sunflower {

struct PlantShape {
	// Model units from each part's root to the next one's: bottom → middle, middle → head, and the
	// head's own length. The default sunflower's parts are one unit each.
	static constexpr float PART_LENGTH = float(param::PLANT_PART_LENGTH.default_value);
	static constexpr glm::vec3 PART_LENGTHS{ PART_LENGTH, PART_LENGTH, PART_LENGTH };
	// The middle part is stretched to (1 + α × this) of its length, α ∈ [0, 0.5) per plant (thesis:
	// s' = s + α/10), for variety in height.
	static constexpr float MIDDLE_VARIATION = float(param::PLANT_MIDDLE_VARIATION.default_value);
	// Model units from the root to the top of anything drawn: the stacked parts (3 units, the middle
	// up to 1.05 with the variation) and the nodding head's petals above them; the impostor quads
	// frame exactly this height.
	static constexpr float HEIGHT = float(param::PLANT_HEIGHT_UNITS.default_value);
	// Radius of the sphere about the plant's middle (height / 2 up) that holds the whole plant
	// leaning by the largest bend (45°) with its leaves (half-width ~0.8): what frustum culling and
	// chunk bounds use. Smaller radii cut swaying heads at the screen edge.
	static constexpr float CULL_RADIUS = float(param::PLANT_CULL_RADIUS_UNITS.default_value);

	glm::vec3 part_lengths = PART_LENGTHS;
	float middle_variation = MIDDLE_VARIATION;
	float height = HEIGHT; // model units
	float cull_radius = CULL_RADIUS; // model units
	// How stiff the plant is against the wind's stiffnesses (SunflowerWind's d1, d2): 2 bends half as
	// far as the sunflower, 0.5 twice as far.
	float stiffness = float(param::PLANT_STIFFNESS.default_value);
	// Metres per model unit: a plant `plant_height` metres tall from its root to the top of its
	// parts is drawn at plant_height / parts_height().
	float part_scale = float(param::PLANT_HEIGHT.default_value) / (PART_LENGTHS.x + PART_LENGTHS.y + PART_LENGTHS.z);

	// The plant type's level-of-detail switch distances are the field's (LodParams::distances, set
	// for the 2 m sunflower) times this: a plant type of its own size switches where it looks the
	// same (the addon passes its height over 2 m unless the plant says otherwise).
	float lod_scale = 1.0f;
	// The squared distances a LodSelector of the field's distances compares for this plant type.
	float lod_distance_sq(float p_distance_sq) const { return p_distance_sq / (lod_scale * lod_scale); }

	// Whether the near levels draw a plant as one instance (WholePlant: its parts in one mesh, placed
	// by the shader) instead of one instance per part.
	bool whole = false;

	float parts_height() const { return part_lengths.x + part_lengths.y + part_lengths.z; }
	// Sets the SunflowerPlant row p_spec of the form in model units from its values
	// (FieldSimulation::set_setting; the height in metres is FieldPlants::shape_of_height's).
	RowSet set(const ParameterSpec &p_spec, const float *p_values);
	// A stalk collider's radius as a share of the parts' height (5 cm for a 2 m sunflower).
	static constexpr float STALK_RADIUS_SHARE = 0.025f;
	bool operator==(const PlantShape &p_other) const {
		return part_lengths == p_other.part_lengths && middle_variation == p_other.middle_variation &&
				height == p_other.height && cull_radius == p_other.cull_radius && part_scale == p_other.part_scale &&
				stiffness == p_other.stiffness && lod_scale == p_other.lod_scale && whole == p_other.whole;
	}
};

} // namespace sunflower
