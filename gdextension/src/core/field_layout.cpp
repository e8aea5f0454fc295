#include "field_layout.h"

#include "random_hash.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace sunflower {

glm::vec2 Plant::tone(const PlantVariety &p_variety) const {
	if (p_variety.brightness <= 0.0f && p_variety.tint <= 0.0f) {
		return glm::vec2(1.0f, 0.0f);
	}
	uint32_t x_bits = 0;
	uint32_t z_bits = 0;
	std::memcpy(&x_bits, &position.x, sizeof(x_bits));
	std::memcpy(&z_bits, &position.y, sizeof(z_bits));
	const uint64_t hash = hash_plant(uint64_t(x_bits) << 32 | z_bits, 0, STREAM_COLOR);
	const float brightness = 1.0f + (unit_float(hash) * 2.0f - 1.0f) * p_variety.brightness;
	const float warmth = (unit_float(hash << 24) * 2.0f - 1.0f) * p_variety.tint;
	return glm::vec2(brightness, warmth);
}

glm::vec4 Plant::color(const PlantVariety &p_variety) const {
	return tone_colour(tone(p_variety));
}

namespace {

// The key of a cell's randomness: its place in the map, so painting one cell changes no other plant.
uint64_t cell_key(const FieldMap &p_map, int p_column, int p_row) {
	return uint64_t(p_row) * uint64_t(p_map.columns) + uint64_t(p_column);
}

// The root (x, z) of the plant of a map's plant cell, and its α: the thesis' rule, seeded per cell.
glm::vec2 plant_root(const LayoutParams &p_params, uint64_t p_key, int p_column, int p_row, float &r_alpha) {
	const float jitter = std::clamp(p_params.jitter, 0.0f, LayoutParams::MAX_JITTER);
	r_alpha = unit_float(hash_plant(p_params.seed, p_key, STREAM_ALPHA)) * jitter;
	const float alpha_z = p_params.independent_jitter ? unit_float(hash_plant(p_params.seed, p_key, STREAM_ALPHA_Z)) * jitter : r_alpha;
	return glm::vec2((float(p_column) + r_alpha) * p_params.cell_size, (float(p_row) + alpha_z) * p_params.cell_size);
}

glm::vec2 object_centre(const LayoutParams &p_params, const MapObject &p_object) {
	return (glm::vec2(float(p_object.column), float(p_object.row)) + 0.5f) * p_params.cell_size;
}

} // namespace

glm::vec2 plant_root_at(const FieldMap &p_map, const LayoutParams &p_params, int p_column, int p_row) {
	float alpha = 0.0f;
	return plant_root(p_params, cell_key(p_map, p_column, p_row), p_column, p_row, alpha);
}

Plant lay_plant(const FieldMap &p_map, const LayoutParams &p_params, uint32_t p_species, int p_column, int p_row) {
	const PlantVariety &variety = p_params.varieties[p_species % FieldMap::MAX_SPECIES];
	Plant plant;
	const uint64_t key = cell_key(p_map, p_column, p_row);
	float alpha = 0.0f;
	plant.position = plant_root(p_params, key, p_column, p_row, alpha);
	plant.set_alpha(alpha);
	plant.yaw = (unit_float(hash_plant(p_params.seed, key, STREAM_YAW)) * 2.0f - 1.0f) * variety.yaw_range;
	plant.scale = variety.scale_min +
			(variety.scale_max - variety.scale_min) * unit_float(hash_plant(p_params.seed, key, STREAM_SCALE));
	return plant;
}

void ground_points(const FieldMap &p_map, const LayoutParams &p_params, std::vector<glm::vec2> &r_points) {
	r_points.clear();
	r_points.reserve(size_t(p_map.plant_count) + p_map.objects.size());
	float alpha = 0.0f;
	for (int row = 0; row < p_map.rows; ++row) {
		for (int column = 0; column < p_map.columns; ++column) {
			if (p_map.has_plant(column, row)) {
				r_points.push_back(plant_root(p_params, cell_key(p_map, column, row), column, row, alpha));
			}
		}
	}
	for (const MapObject &object : p_map.objects) {
		r_points.push_back(object_centre(p_params, object));
	}
}

void build_layout(const FieldMap &p_map, const LayoutParams &p_params, const Ground &p_ground, FieldLayout &r_layout) {
	r_layout.plants.clear();
	r_layout.chunks.clear();
	r_layout.chunk_plants.clear();
	r_layout.grid_chunks.clear();
	r_layout.object_ground.clear();
	r_layout.cells_without_ground = 0;
	r_layout.plants.reserve(static_cast<size_t>(p_map.plant_count));
	r_layout.size = glm::vec2(float(p_map.columns), float(p_map.rows)) * p_params.cell_size;

	float chunk_size = std::max(p_params.chunk_size, p_params.cell_size);
	const auto chunks_along = [&](float p_metres) { return std::max(1, static_cast<int>(std::ceil(p_metres / chunk_size))); };
	while (int64_t(chunks_along(r_layout.size.x)) * chunks_along(r_layout.size.y) > FieldLayout::MAX_CHUNK_CELLS) {
		chunk_size *= 2.0f;
	}
	const int chunks_x = chunks_along(r_layout.size.x);
	const int chunks_z = chunks_along(r_layout.size.y);
	const size_t cells = static_cast<size_t>(chunks_x) * static_cast<size_t>(chunks_z);
	const uint32_t species_count = uint32_t(std::clamp(p_map.species_count, 1, FieldMap::MAX_SPECIES));
	// Plants per (grid cell, species): the chunks to be.
	std::vector<uint32_t> key_count(cells * species_count, 0);
	r_layout.grid_x = chunks_x;
	r_layout.grid_z = chunks_z;
	r_layout.chunk_size = chunk_size;

	// Listed heights of another count than the ground points belong to another map: no ground.
	const bool ground_fits = p_ground.kind != Ground::HEIGHTS ||
			p_ground.heights.size() == size_t(p_map.plant_count) + p_map.objects.size();
	uint64_t index = 0; // the plant cell's, in map order: also its ground point
	for (int row = 0; row < p_map.rows; ++row) {
		for (int column = 0; column < p_map.columns; ++column) {
			if (!p_map.has_plant(column, row)) {
				continue;
			}
			const uint32_t species = std::min(uint32_t(p_map.species_at(column, row)), species_count - 1);
			Plant plant = lay_plant(p_map, p_params, species, column, row);
			plant.ground = ground_fits ? p_ground.height_at(uint32_t(index), plant.position) : NAN;
			if (!std::isfinite(plant.ground)) {
				++r_layout.cells_without_ground;
				++index;
				continue;
			}
			plant.set_lean(p_ground.lean_at(uint32_t(index), plant.position));
			plant.chunk = r_layout.grid_cell(plant.position) * species_count + species; // key for now
			++key_count[plant.chunk];
			r_layout.plants.push_back(plant);
			++index;
		}
	}
	r_layout.object_ground.reserve(p_map.objects.size());
	for (const MapObject &object : p_map.objects) {
		const float height = ground_fits ? p_ground.height_at(uint32_t(index), object_centre(p_params, object)) : NAN;
		++index;
		r_layout.object_ground.push_back(std::isfinite(height) ? height : NAN);
	}

	// Compact the keys to the chunks that hold plants, cell by cell, then group plant indices by chunk.
	std::vector<uint32_t> key_to_chunk(key_count.size(), 0);
	r_layout.grid_chunks.assign(cells + 1, 0);
	uint32_t offset = 0;
	for (size_t key = 0; key < key_count.size(); ++key) {
		if (key_count[key] != 0) {
			key_to_chunk[key] = static_cast<uint32_t>(r_layout.chunks.size());
			r_layout.chunks.push_back(Chunk::empty(static_cast<uint32_t>(key % species_count), offset));
			offset += key_count[key];
		}
		r_layout.grid_chunks[key / species_count + 1] = static_cast<uint32_t>(r_layout.chunks.size());
	}
	r_layout.chunk_plants.resize(r_layout.plants.size());
	for (uint32_t i = 0; i < r_layout.plants.size(); ++i) {
		Plant &plant = r_layout.plants[i];
		plant.chunk = key_to_chunk[plant.chunk];
		Chunk &chunk = r_layout.chunks[plant.chunk];
		r_layout.chunk_plants[chunk.first + chunk.count++] = i;
		chunk.include(plant);
	}
}

namespace {

// The layout's settings of one float each and a plant type's variety's, by their table rows.
constexpr FloatRow<LayoutParams> LAYOUT_ROWS[] = { { &param::CELL_SIZE, &LayoutParams::cell_size },
	{ &param::CHUNK_SIZE, &LayoutParams::chunk_size }, { &param::TILE_MERGE_DISTANCE, &LayoutParams::tile_merge_distance } };
constexpr FloatRow<PlantVariety> VARIETY_ROWS[] = { { &param::PLANT_YAW_RANGE, &PlantVariety::yaw_range },
	{ &param::PLANT_SCALE_MIN, &PlantVariety::scale_min }, { &param::PLANT_SCALE_MAX, &PlantVariety::scale_max },
	{ &param::PLANT_BRIGHTNESS_VARIATION, &PlantVariety::brightness }, { &param::PLANT_TINT_VARIATION, &PlantVariety::tint } };

} // namespace

RowSet PlantVariety::set(const ParameterSpec &p_spec, float p_value) {
	return set_float_row(*this, VARIETY_ROWS, p_spec, p_value);
}

RowSet LayoutParams::set(const ParameterSpec &p_spec, float p_value, uint32_t p_species) {
	const RowSet set = set_float_row(*this, LAYOUT_ROWS, p_spec, p_value);
	return set != RowSet::OTHER || p_species >= varieties.size() ? set : varieties[p_species].set(p_spec, p_value);
}

LayoutParams LayoutParams::sanitized(const LayoutParams &p_current) const {
	LayoutParams params = *this;
	for (const FloatRow<LayoutParams> &row : LAYOUT_ROWS) {
		params.*row.member = sanitize(*row.spec, this->*row.member, p_current.*row.member);
	}
	for (size_t s = 0; s < params.varieties.size(); ++s) {
		PlantVariety &variety = params.varieties[s];
		for (const FloatRow<PlantVariety> &row : VARIETY_ROWS) {
			variety.*row.member = sanitize(*row.spec, varieties[s].*row.member, p_current.varieties[s].*row.member);
		}
		variety.scale_max = std::max(variety.scale_min, variety.scale_max);
	}
	return params;
}

} // namespace sunflower
