#include "field_layout.h"

#include "random_hash.h"

#include <algorithm>
#include <cmath>

namespace sunflower {

void build_layout(const FieldMap &p_map, const LayoutParams &p_params, FieldLayout &r_layout) {
	r_layout.plants.clear();
	r_layout.chunks.clear();
	r_layout.chunk_plants.clear();
	r_layout.grid_chunks.clear();
	r_layout.plants.reserve(static_cast<size_t>(p_map.plant_count));
	r_layout.size = glm::vec2(float(p_map.columns), float(p_map.rows)) * p_params.cell_size;

	const float chunk_size = std::max(p_params.chunk_size, p_params.cell_size);
	const int chunks_x = std::max(1, static_cast<int>(std::ceil(r_layout.size.x / chunk_size)));
	const int chunks_z = std::max(1, static_cast<int>(std::ceil(r_layout.size.y / chunk_size)));
	std::vector<uint32_t> grid_count(static_cast<size_t>(chunks_x) * static_cast<size_t>(chunks_z), 0);
	r_layout.grid_x = chunks_x;
	r_layout.grid_z = chunks_z;
	r_layout.chunk_size = chunk_size;

	uint64_t index = 0;
	for (int row = 0; row < p_map.rows; ++row) {
		for (int column = 0; column < p_map.columns; ++column) {
			if (!p_map.has_plant(column, row)) {
				continue;
			}
			Plant plant;
			plant.alpha = unit_float(hash_plant(p_params.seed, index, STREAM_ALPHA)) * p_params.jitter;
			const float alpha_z = p_params.independent_jitter
					? unit_float(hash_plant(p_params.seed, index, STREAM_ALPHA_Z)) * p_params.jitter
					: plant.alpha;
			plant.position = glm::vec2((float(column) + plant.alpha) * p_params.cell_size,
					(float(row) + alpha_z) * p_params.cell_size);
			plant.yaw = (unit_float(hash_plant(p_params.seed, index, STREAM_YAW)) * 2.0f - 1.0f) * p_params.yaw_jitter;
			const int cx = std::min(chunks_x - 1, static_cast<int>(plant.position.x / chunk_size));
			const int cz = std::min(chunks_z - 1, static_cast<int>(plant.position.y / chunk_size));
			plant.chunk = static_cast<uint32_t>(cz * chunks_x + cx);
			++grid_count[plant.chunk];
			r_layout.plants.push_back(plant);
			++index;
		}
	}

	// Compact the grid to the chunks that hold plants, then group plant indices by chunk.
	std::vector<uint32_t> &grid_to_chunk = r_layout.grid_chunks;
	grid_to_chunk.assign(grid_count.size(), FieldLayout::NO_CHUNK);
	uint32_t offset = 0;
	for (size_t g = 0; g < grid_count.size(); ++g) {
		if (grid_count[g] == 0) {
			continue;
		}
		grid_to_chunk[g] = static_cast<uint32_t>(r_layout.chunks.size());
		Chunk chunk;
		chunk.first = offset;
		chunk.min = glm::vec2(INFINITY);
		chunk.max = glm::vec2(-INFINITY);
		r_layout.chunks.push_back(chunk);
		offset += grid_count[g];
	}
	r_layout.chunk_plants.resize(r_layout.plants.size());
	for (uint32_t i = 0; i < r_layout.plants.size(); ++i) {
		Plant &plant = r_layout.plants[i];
		plant.chunk = grid_to_chunk[plant.chunk];
		Chunk &chunk = r_layout.chunks[plant.chunk];
		r_layout.chunk_plants[chunk.first + chunk.count++] = i;
		chunk.min = glm::min(chunk.min, plant.position);
		chunk.max = glm::max(chunk.max, plant.position);
	}
}

} // namespace sunflower
