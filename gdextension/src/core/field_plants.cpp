#include "field_plants.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace sunflower {

bool FieldPlants::load_map(const std::string &p_text, const std::u32string &p_legend, const std::u32string &p_plant_symbols,
		const std::string &p_source, const MapLimits &p_limits, MapError &r_error) {
	FieldMap parsed;
	if (!parse_field_map(p_text, p_legend, p_plant_symbols, p_source, p_limits, parsed, r_error)) {
		return false;
	}
	_map = std::move(parsed);
	_plant_symbols = p_plant_symbols;
	_rebuild();
	return true;
}

void FieldPlants::replace_map(FieldMap p_map) {
	_map = std::move(p_map);
	_rebuild();
}

bool FieldPlants::paint_map(const glm::vec2 &p_center, float p_radius, const CellContent &p_content, float p_density,
		uint64_t p_seed, bool p_relayout, std::vector<int> &r_changed, const CellWeights *p_weights) {
	const size_t before = r_changed.size();
	paint_cells(_map, p_center.x, p_center.y, p_radius, p_content, p_density, p_seed, r_changed, p_weights);
	if (!p_relayout || r_changed.size() == before) {
		return false;
	}
	_rebuild();
	return true;
}

bool FieldPlants::set_layout_params(const LayoutParams &p_params) {
	const LayoutParams params = p_params.sanitized(_layout_params);
	if (params == _layout_params) {
		return false;
	}
	_layout_params = params;
	_rebuild();
	return true;
}

void FieldPlants::set_ground(Ground p_ground) {
	p_ground.tilt = sanitize(param::GROUND_TILT, p_ground.tilt, _ground.tilt);
	_ground = std::move(p_ground);
	_rebuild();
}

namespace {

// A plant type's form's settings of one float each, by their table rows.
constexpr FloatRow<PlantShape> SHAPE_ROWS[] = { { &param::PLANT_MIDDLE_VARIATION, &PlantShape::middle_variation },
	{ &param::PLANT_HEIGHT_UNITS, &PlantShape::height }, { &param::PLANT_CULL_RADIUS_UNITS, &PlantShape::cull_radius },
	{ &param::PLANT_STIFFNESS, &PlantShape::stiffness } };

} // namespace

RowSet PlantShape::set(const ParameterSpec &p_spec, const float *p_values) {
	if (&p_spec != &param::PLANT_PART_LENGTH) {
		return set_float_row(*this, SHAPE_ROWS, p_spec, p_values[0]);
	}
	glm::vec3 lengths = part_lengths;
	for (int i = 0; i < 3; ++i) {
		lengths[i] = sanitize(p_spec, p_values[i], part_lengths[i]);
	}
	if (!(lengths.x + lengths.y + lengths.z > 0.0f) || lengths == part_lengths) {
		return RowSet::SAME; // a plant of no height could not be scaled to one
	}
	part_lengths = lengths;
	return RowSet::CHANGED;
}

bool FieldPlants::set_shape(const PlantShape &p_shape, uint32_t p_species) {
	if (p_species >= _shapes.size()) {
		return false;
	}
	PlantShape &current = _shapes[p_species];
	PlantShape shape = p_shape;
	for (int i = 0; i < 3; ++i) {
		shape.part_lengths[i] = sanitize(param::PLANT_PART_LENGTH, shape.part_lengths[i], current.part_lengths[i]);
	}
	if (!(shape.parts_height() > 0.0f)) {
		shape.part_lengths = current.part_lengths; // a plant of no height could not be scaled to one
	}
	for (const FloatRow<PlantShape> &row : SHAPE_ROWS) {
		shape.*row.member = sanitize(*row.spec, p_shape.*row.member, current.*row.member);
	}
	shape.part_scale = shape.part_scale > 0.0f && std::isfinite(shape.part_scale) ? shape.part_scale : current.part_scale;
	shape.lod_scale = shape.lod_scale > 0.0f && std::isfinite(shape.lod_scale) ? shape.lod_scale : current.lod_scale;
	const bool drawn_otherwise = shape.whole != current.whole;
	current = shape;
	_chunk_signatures.clear(); // the impostors' scale may have changed
	return drawn_otherwise;
}

PlantShape FieldPlants::shape_of_height(float p_metres, uint32_t p_species) const {
	PlantShape shape = get_shape(p_species);
	const float parts = shape.parts_height();
	shape.part_scale = sanitize(param::PLANT_HEIGHT, p_metres, shape.part_scale * parts) / parts;
	return shape;
}

void FieldPlants::_rebuild() {
	build_layout(_map, _layout_params, _ground, _layout);
	_chunk_cells.assign(_layout.chunks.size(), 0);
	for (size_t cell = 0; cell + 1 < _layout.grid_chunks.size(); ++cell) {
		for (uint32_t c = _layout.grid_chunks[cell]; c < _layout.grid_chunks[cell + 1]; ++c) {
			_chunk_cells[c] = static_cast<uint32_t>(cell);
		}
	}
	_chunk_signatures.clear(); // the shape or variety may have changed too: computed anew
	_plant_states.clear(); // every plant index may have changed: FieldSimulation sets them again
	_plant_cells.clear();
	_map_plant_count = static_cast<uint32_t>(_layout.plants.size());
	_map_chunk_count = static_cast<uint32_t>(_layout.chunks.size());
	_added_cells.clear();
	_added_species.clear();
	_free_added.clear();
	_added_at_cell.clear();
	_added_grouped = true;
}

ChunkBounds FieldPlants::get_chunk_bounds(uint32_t p_chunk) const {
	const Chunk &chunk = _layout.chunks[p_chunk];
	const PlantShape &shape = _shapes[chunk.species];
	const float scale = shape.part_scale * chunk.scale_max;
	const float reach = shape.cull_radius * scale;
	ChunkBounds bounds;
	bounds.min = glm::vec3(chunk.min.x - reach, chunk.ground_min, chunk.min.y - reach);
	bounds.max = glm::vec3(chunk.max.x + reach, chunk.ground_max + shape.height * scale * 1.05f, chunk.max.y + reach);
	return bounds;
}

GridRange FieldPlants::grid_range(const glm::vec2 &p_center, float p_reach) const {
	const float size = _layout.chunk_size;
	GridRange range;
	range.x0 = std::max(0, static_cast<int>(std::floor((p_center.x - p_reach) / size)));
	range.x1 = std::min(_layout.grid_x - 1, static_cast<int>(std::floor((p_center.x + p_reach) / size)));
	range.z0 = std::max(0, static_cast<int>(std::floor((p_center.y - p_reach) / size)));
	range.z1 = std::min(_layout.grid_z - 1, static_cast<int>(std::floor((p_center.y + p_reach) / size)));
	return range;
}

void FieldPlants::find_plants_near(const glm::vec2 &p_center, float p_radius, std::vector<uint32_t> &r_plants) const {
	if (_layout.chunks.empty() || !(p_radius >= 0.0f) || !std::isfinite(p_radius) || !std::isfinite(p_center.x) ||
			!std::isfinite(p_center.y)) {
		return;
	}
	const float radius_sq = p_radius * p_radius;
	const auto gather = [&](const Chunk &p_chunk) {
		for (uint32_t k = 0; k < p_chunk.count; ++k) {
			const uint32_t index = _layout.chunk_plants[p_chunk.first + k];
			const glm::vec2 d = _layout.plants[index].position - p_center;
			if (glm::dot(d, d) < radius_sq) {
				r_plants.push_back(index);
			}
		}
	};
	const GridRange cells = grid_range(p_center, p_radius);
	for (int z = cells.z0; z <= cells.z1; ++z) {
		for (int x = cells.x0; x <= cells.x1; ++x) {
			const size_t cell = static_cast<size_t>(z) * size_t(_layout.grid_x) + size_t(x);
			for (uint32_t c = _layout.grid_chunks[cell]; c < _layout.grid_chunks[cell + 1]; ++c) {
				gather(_layout.chunks[c]);
			}
		}
	}
	// The added plants' chunks lie outside the grid's lists: each by its bounds.
	for (uint32_t c = _map_chunk_count; c < _layout.chunks.size(); ++c) {
		const Chunk &chunk = _layout.chunks[c];
		const glm::vec2 nearest = glm::clamp(p_center, chunk.min, chunk.max);
		if (glm::dot(nearest - p_center, nearest - p_center) < radius_sq) {
			gather(chunk);
		}
	}
}

float FieldPlants::get_plant_reach() const {
	float reach = 0.0f;
	for (uint32_t species = 0; species < get_species_count(); ++species) {
		const PlantShape &shape = _shapes[species];
		reach = std::max(reach, shape.cull_radius * shape.part_scale * _layout_params.varieties[species].scale_max);
	}
	return reach;
}

float FieldPlants::plant_distance_sq(const Plant &p_plant, const glm::vec3 &p_eye) const {
	const PlantShape &shape = _shapes[species_of(p_plant)];
	const glm::vec3 d = p_eye - (p_plant.root() + glm::vec3(0.0f, 0.5f * shape.height * shape.part_scale * p_plant.scale, 0.0f));
	return glm::dot(d, d);
}

glm::vec2 FieldPlants::get_stalk(uint32_t p_plant) const {
	const Plant &plant = _layout.plants[p_plant];
	const PlantShape &shape = _shapes[species_of(plant)];
	const float scale = shape.part_scale * plant.scale;
	const float middle = 1.0f + plant.alpha() * shape.middle_variation; // as the parts stack (wind_model.cpp)
	return glm::vec2(PlantShape::STALK_RADIUS_SHARE * shape.parts_height(), shape.part_lengths.x + shape.part_lengths.y * middle) * scale;
}

FarInstance FieldPlants::far_instance(const Plant &p_plant, uint32_t p_species) const {
	FarInstance instance;
	instance.root = p_plant.root();
	instance.yaw = p_plant.yaw;
	instance.scale = _shapes[p_species].part_scale * p_plant.scale;
	instance.lean = p_plant.lean();
	instance.tone = p_plant.tone(_layout_params.varieties[p_species]);
	return instance;
}

void FieldPlants::write_records(uint32_t p_chunk, const uint32_t *p_plants, uint32_t p_count, float *r_out,
		uint32_t p_levels_above) const {
	const uint32_t species = _layout.chunks[p_chunk].species;
	for (uint32_t k = 0; k < p_count; ++k) {
		FarInstance instance = far_instance(_layout.plants[p_plants[k]], species);
		instance.cell = _chunk_cells[p_chunk];
		instance.levels_above = p_levels_above;
		write_far_instance(r_out + size_t(k) * FAR_FLOATS_PER_INSTANCE, instance);
	}
}

void FieldPlants::write_chunk_instances(uint32_t p_chunk, float *r_out) const {
	const Chunk &chunk = _layout.chunks[p_chunk];
	write_records(p_chunk, _layout.chunk_plants.data() + chunk.first, chunk.count, r_out);
}

uint64_t FieldPlants::get_chunk_key(uint32_t p_chunk) const {
	return uint64_t(_chunk_cells[p_chunk]) * FieldMap::MAX_SPECIES + _layout.chunks[p_chunk].species;
}

uint64_t FieldPlants::get_chunk_signature(uint32_t p_chunk) const {
	if (p_chunk < _chunk_signatures.size() && _chunk_signatures[p_chunk] != 0) {
		return _chunk_signatures[p_chunk];
	}
	const uint32_t count = _layout.chunks[p_chunk].count;
	std::vector<float> instances(size_t(count) * FAR_FLOATS_PER_INSTANCE);
	write_chunk_instances(p_chunk, instances.data());
	// FNV-1a over the bytes of the instance data, never 0.
	uint64_t hash = 1469598103934665603ull ^ count;
	const uint8_t *bytes = reinterpret_cast<const uint8_t *>(instances.data());
	for (size_t i = 0; i < instances.size() * sizeof(float); ++i) {
		hash = (hash ^ bytes[i]) * 1099511628211ull;
	}
	return hash == 0 ? 1 : hash;
}

void FieldPlants::compute_chunk_signatures() {
	_chunk_signatures.assign(_layout.chunks.size(), 0);
	for (uint32_t c = 0; c < _layout.chunks.size(); ++c) {
		_chunk_signatures[c] = get_chunk_signature(c);
	}
}

size_t FieldPlants::get_memory_bytes() const {
	size_t bytes = _map.plants.capacity() + _map.objects.capacity() * sizeof(MapObject);
	bytes += _layout.plants.capacity() * sizeof(Plant) + _layout.chunks.capacity() * sizeof(Chunk);
	bytes += _layout.chunk_plants.capacity() * sizeof(uint32_t);
	bytes += _layout.grid_chunks.capacity() * sizeof(uint32_t) + _layout.object_ground.capacity() * sizeof(float);
	bytes += (_ground.grid.heights.capacity() + _ground.heights.capacity() + _ground.normals.capacity()) * sizeof(float);
	bytes += _chunk_cells.capacity() * sizeof(uint32_t) + _chunk_signatures.capacity() * sizeof(uint64_t);
	bytes += _plant_states.capacity() + _plant_cells.capacity() * sizeof(uint32_t);
	bytes += (_added_cells.capacity() + _added_species.capacity() + _free_added.capacity()) * sizeof(uint32_t) +
			_added_at_cell.size() * 32;
	return bytes;
}

void FieldPlants::set_plant_state(uint32_t p_plant, PlantState p_state) {
	if (p_plant >= _layout.plants.size() || get_plant_state(p_plant) == p_state) {
		return;
	}
	_plant_states.resize(_layout.plants.size(), static_cast<uint8_t>(PlantState::STANDING));
	_plant_states[p_plant] = static_cast<uint8_t>(p_state);
}

bool FieldPlants::_index_cells() const {
	if (_plant_cells.size() == _map_plant_count) {
		return true;
	}
	// The plants are the map's plant cells in map order, less those without ground: each plant is
	// the next plant cell whose root is where the layout put it.
	_plant_cells.clear();
	_plant_cells.reserve(_map_plant_count);
	for (int row = 0; row < _map.rows && _plant_cells.size() < _map_plant_count; ++row) {
		for (int column = 0; column < _map.columns && _plant_cells.size() < _map_plant_count; ++column) {
			if (_map.has_plant(column, row) &&
					_layout.plants[_plant_cells.size()].position == plant_root_at(_map, _layout_params, column, row)) {
				_plant_cells.push_back(static_cast<uint32_t>(row) * static_cast<uint32_t>(_map.columns) +
						static_cast<uint32_t>(column));
			}
		}
	}
	if (_plant_cells.size() != _map_plant_count) {
		_plant_cells.clear();
		return false; // (never: the layout is made from this map)
	}
	return true;
}

uint32_t FieldPlants::plant_at_cell(uint32_t p_cell) const {
	if (!_index_cells()) {
		return NO_PLANT;
	}
	// The cells are sorted and, in most maps, nearly every cell holds a plant: start where the cell's
	// share of the map puts it and widen by doubling steps (a few memory reads where a bisection of a
	// million plants takes twenty, each likely a cache miss once the frame has been drawn).
	const size_t count = _plant_cells.size();
	const uint64_t cells = uint64_t(std::max(_map.columns, 1)) * uint64_t(std::max(_map.rows, 1));
	if (count == 0 || p_cell >= cells) {
		return NO_PLANT;
	}
	const size_t guess = std::min<size_t>(count - 1, size_t(uint64_t(p_cell) * count / cells));
	size_t low = guess;
	size_t high = guess + 1; // the cell lies in [low, high) if anywhere
	for (size_t step = 1; low > 0 && _plant_cells[low] > p_cell; step *= 2) {
		high = low;
		low = low > step ? low - step : 0;
	}
	for (size_t step = 1; high < count && _plant_cells[high - 1] < p_cell; step *= 2) {
		low = high;
		high = std::min(count, high + step);
	}
	const auto first = _plant_cells.begin() + std::ptrdiff_t(low);
	const auto found = std::lower_bound(first, _plant_cells.begin() + std::ptrdiff_t(high), p_cell);
	return found != _plant_cells.end() && *found == p_cell ? static_cast<uint32_t>(found - _plant_cells.begin()) : NO_PLANT;
}

uint32_t FieldPlants::cell_of_plant(uint32_t p_plant) const {
	if (p_plant >= _map_plant_count) {
		return p_plant - _map_plant_count < _added_cells.size() ? _added_cells[p_plant - _map_plant_count] : NO_CELL;
	}
	return _index_cells() ? _plant_cells[p_plant] : NO_CELL;
}

uint32_t FieldPlants::added_plant_at_cell(uint32_t p_cell) const {
	const auto found = _added_at_cell.find(p_cell);
	return found != _added_at_cell.end() ? found->second : NO_PLANT;
}

uint32_t FieldPlants::add_plant(uint32_t p_cell, uint32_t p_species, float p_height, uint32_t p_map_plant) {
	const uint32_t columns = uint32_t(std::max(_map.columns, 0));
	if (columns == 0 || p_cell >= columns * uint32_t(std::max(_map.rows, 0)) || p_species >= get_species_count()) {
		return NO_PLANT;
	}
	const uint32_t existing = added_plant_at_cell(p_cell);
	if (existing != NO_PLANT && _added_species[existing - _map_plant_count] == p_species) {
		set_plant_state(existing, PlantState::STANDING);
		return existing;
	}
	if (existing != NO_PLANT) {
		take_plant(existing);
	}
	const int column = int(p_cell % columns);
	const int row = int(p_cell / columns);
	Plant plant = lay_plant(_map, _layout_params, p_species, column, row);
	if (std::isfinite(p_height)) {
		plant.ground = p_height;
	} else if (p_map_plant != NO_PLANT) {
		plant.ground = _layout.plants[p_map_plant].ground; // the map's plant stood there: its ground and lean
		plant.set_lean(_layout.plants[p_map_plant].lean());
	} else if (_ground.kind != Ground::HEIGHTS) {
		plant.ground = _ground.height_at(0, plant.position);
		plant.set_lean(_ground.lean_at(0, plant.position));
	} else {
		plant.ground = NAN; // measured ground points only: none there
	}
	if (!std::isfinite(plant.ground)) {
		return NO_PLANT;
	}
	plant.chunk = NO_CHUNK; // until group_added()
	uint32_t index = static_cast<uint32_t>(_layout.plants.size());
	if (!_free_added.empty()) { // the slot of a plant taken before: sowing and harvesting do not grow the field
		index = _free_added.back();
		_free_added.pop_back();
		_layout.plants[index] = plant;
		_added_cells[index - _map_plant_count] = p_cell;
		_added_species[index - _map_plant_count] = p_species;
		if (!_plant_states.empty()) {
			_plant_states[index] = static_cast<uint8_t>(PlantState::STANDING);
		}
	} else {
		_layout.plants.push_back(plant);
		_added_cells.push_back(p_cell);
		_added_species.push_back(p_species);
		if (!_plant_states.empty()) {
			_plant_states.push_back(static_cast<uint8_t>(PlantState::STANDING));
		}
	}
	_added_at_cell[p_cell] = index;
	_added_grouped = false;
	return index;
}

void FieldPlants::take_plant(uint32_t p_plant) {
	if (p_plant < _map_plant_count || p_plant - _map_plant_count >= _added_cells.size() ||
			_added_cells[p_plant - _map_plant_count] == NO_CELL) {
		return;
	}
	set_plant_state(p_plant, PlantState::GONE);
	_added_at_cell.erase(_added_cells[p_plant - _map_plant_count]);
	_added_cells[p_plant - _map_plant_count] = NO_CELL;
	_free_added.push_back(p_plant);
	_added_grouped = false;
}

bool FieldPlants::group_added() {
	if (_added_grouped) {
		return false;
	}
	_added_grouped = true;
	_layout.chunks.resize(_map_chunk_count);
	_layout.chunk_plants.resize(_map_plant_count);
	_chunk_cells.resize(_map_chunk_count);
	// The added plants that are there, by (grid cell, species), then index: a chunk lists its plants in
	// index order (NearField finds a plant's place in its chunk by bisection).
	std::vector<std::pair<uint64_t, uint32_t>> keyed;
	keyed.reserve(_added_at_cell.size());
	for (uint32_t i = 0; i < _added_cells.size(); ++i) {
		Plant &plant = _layout.plants[_map_plant_count + i];
		plant.chunk = NO_CHUNK;
		if (_added_cells[i] != NO_CELL) {
			const uint64_t cell = _layout.grid_cell(plant.position);
			keyed.push_back({ cell * FieldMap::MAX_SPECIES + _added_species[i], _map_plant_count + i });
		}
	}
	std::sort(keyed.begin(), keyed.end());
	for (size_t k = 0; k < keyed.size(); ++k) {
		if (k == 0 || keyed[k].first != keyed[k - 1].first) {
			_layout.chunks.push_back(Chunk::empty(static_cast<uint32_t>(keyed[k].first % FieldMap::MAX_SPECIES),
					static_cast<uint32_t>(_layout.chunk_plants.size())));
			_chunk_cells.push_back(static_cast<uint32_t>(keyed[k].first / FieldMap::MAX_SPECIES));
		}
		Plant &plant = _layout.plants[keyed[k].second];
		plant.chunk = static_cast<uint32_t>(_layout.chunks.size() - 1);
		_layout.chunk_plants.push_back(keyed[k].second);
		++_layout.chunks.back().count;
		_layout.chunks.back().include(plant);
	}
	if (!_chunk_signatures.empty()) {
		_chunk_signatures.resize(_layout.chunks.size(), 0);
	}
	return true;
}

} // namespace sunflower
