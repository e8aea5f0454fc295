// Core tests of play's changes drawn by the simulation: cut, flattened and removed plants at every
// level of detail at the next update, without a rebuild; kept through a layout rebuilt for the same
// map, forgotten with another map; regrowth and saves through the simulation.
#include "field_test_support.h"

using namespace sunflower_test;

namespace {

// Whether the hidden-cells mask hides a far record rooted at p_root, as the impostor shader reads it
// (cells of 0.5 m, 200 columns).
bool hidden_at(const FieldSimulation &p_sim, const glm::vec3 &p_root) {
	const std::vector<uint8_t> &hidden = p_sim.get_hidden_cells();
	const int column = int(std::floor(p_root.x / 0.5f + 0.25f));
	const int row = int(std::floor(p_root.z / 0.5f + 0.25f));
	const size_t byte = size_t(row) * p_sim.hidden_row_bytes() + size_t(column / 8);
	return byte < hidden.size() && ((hidden[byte] >> (column % 8)) & 1) != 0;
}

// How many instances of the near buckets of every species (and, with p_tiles, of the far tiles' records the hidden-cells
// mask leaves) stand at p_root with a size: a cut plant has none.
int drawn_at(const FieldSimulation &p_sim, const glm::vec3 &p_root, bool p_tiles) {
	int count = 0;
	for (uint32_t species = 0; species < p_sim.plants().get_species_count(); ++species) {
		for (uint32_t level = 0; level < LOD_MESH_COUNT; ++level) {
			const InstanceBuffer &bucket = p_sim.near().get_bucket(species * BUCKET_COUNT + mesh_bucket(level, 0));
			for (uint32_t i = 0; i < bucket.get_count(); ++i) {
				count += glm::distance(placed(bucket, i).root, p_root) < 1e-4f ? 1 : 0;
			}
		}
		const InstanceBuffer &impostors = p_sim.near().get_bucket(species * BUCKET_COUNT + BUCKET_IMPOSTOR);
		for (uint32_t i = 0; i < impostors.get_count(); ++i) {
			const FarInstance record = read_far_instance(impostors.get_data() + size_t(i) * impostors.get_stride());
			count += glm::distance(record.root, p_root) < 1e-4f && record.scale > 0.0f ? 1 : 0;
		}
	}
	for (uint32_t t = 0; p_tiles && t < p_sim.tiles().get_tile_count(); ++t) {
		std::vector<float> records(size_t(p_sim.tiles().get_tile(t).plants) * FAR_FLOATS_PER_INSTANCE);
		p_sim.tiles().write_tile_instances(t, records.data());
		for (size_t k = 0; k < p_sim.tiles().get_tile(t).plants; ++k) {
			const FarInstance record = read_far_instance(records.data() + k * FAR_FLOATS_PER_INSTANCE);
			count += glm::distance(record.root, p_root) < 1e-4f && record.scale > 0.0f && !hidden_at(p_sim, record.root) ? 1 : 0;
		}
	}
	return count;
}

uint32_t cell(int p_column, int p_row) {
	return static_cast<uint32_t>(p_row * 200 + p_column);
}

} // namespace

TEST_CASE("play: a cut plant is drawn nowhere from the next update on, without a rebuild") {
	FieldSimulation sim;
	load(sim, rect_map(200, 40)); // 100 × 20 m, chunks of 8 m
	sim.near().set_observer({ 5.0f, 1.7f, 5.0f });
	sim.near().request_lod_update();
	sim.update(0.016f);
	const uint32_t near_cell = cell(10, 10); // about 5 m off: a mesh
	const uint32_t far_cell = cell(190, 35); // about 90 m off: a far tile
	const uint32_t middle_cell = cell(55, 35); // about 26 m off: an impostor of an active chunk
	const uint32_t middle_plant = sim.plants().plant_at_cell(middle_cell);
	const uint32_t near_plant = sim.plants().plant_at_cell(near_cell);
	const uint32_t far_plant = sim.plants().plant_at_cell(far_cell);
	REQUIRE(near_plant != FieldPlants::NO_PLANT);
	REQUIRE(far_plant != FieldPlants::NO_PLANT);
	const glm::vec3 near_root = sim.plants().get_layout().plants[near_plant].root();
	const glm::vec3 far_root = sim.plants().get_layout().plants[far_plant].root();
	CHECK(glm::floor(near_root.x / 0.5f) == 10.0f); // the plant of that cell
	CHECK(drawn_at(sim, near_root, false) == 1);
	CHECK(drawn_at(sim, far_root, true) >= 1);
	CHECK_FALSE(sim.near().is_chunk_active(sim.plants().get_layout().plants[far_plant].chunk));
	const glm::vec3 middle_root = sim.plants().get_layout().plants[middle_plant].root();
	REQUIRE(sim.near().is_chunk_active(sim.plants().get_layout().plants[middle_plant].chunk));
	CHECK(sim.near().get_plant_lod(middle_plant) >= LOD_MESH_3);
	CHECK(drawn_at(sim, middle_root, false) >= 1);
	const uint32_t records_version = sim.get_records_version();

	std::vector<uint32_t> changed;
	sim.change_cells({ near_cell, far_cell, near_cell, middle_cell }, FieldSimulation::CellAction::CUT, 1.0, changed);
	CHECK(changed == std::vector<uint32_t>{ near_cell, far_cell, middle_cell }); // a second cut of a cell is none
	sim.update(0.016f);
	CHECK(drawn_at(sim, near_root, false) == 0);
	CHECK(drawn_at(sim, far_root, true) == 0);
	CHECK(drawn_at(sim, middle_root, false) == 0);
	CHECK(sim.get_records_version() == records_version); // no rebuild, no tile written
	CHECK(sim.plants().get_plant_count() == 8000);
	// Another plant of the same chunk is still drawn.
	const uint32_t neighbour = sim.plants().plant_at_cell(cell(11, 10));
	CHECK(drawn_at(sim, sim.plants().get_layout().plants[neighbour].root(), false) == 1);

	// A layout rebuilt for the same map keeps the cut; another map forgets it.
	LayoutParams params = sim.plants().get_layout_params();
	params.chunk_size = 4.0f;
	REQUIRE(sim.set_layout_params(params));
	sim.near().request_lod_update();
	sim.update(0.016f);
	CHECK(sim.plants().get_plant_state(sim.plants().plant_at_cell(near_cell)) == PlantState::CUT);
	CHECK(drawn_at(sim, near_root, true) == 0);
	CHECK(sim.changes().changes().size() == 3);
	std::vector<uint32_t> stood;
	sim.change_cells({ near_cell }, FieldSimulation::CellAction::STAND, 2.0, stood);
	sim.update(0.016f);
	CHECK(drawn_at(sim, near_root, false) == 1);
	MapError error;
	REQUIRE(sim.load_map(rect_map(200, 41), U"", "other", MapLimits{}, error));
	CHECK(sim.changes().changes().empty());
}

TEST_CASE("play: a flattened plant lies bent near and is not drawn far; it stands again when its time comes") {
	FieldSimulation sim;
	load(sim, rect_map(200, 40));
	sim.near().set_observer({ 5.0f, 1.7f, 5.0f });
	sim.near().request_lod_update();
	sim.update(0.016f);
	const uint32_t near_cell = cell(8, 10);
	const uint32_t plant = sim.plants().plant_at_cell(near_cell);
	PartTransforms upright;
	sim.near().get_plant_parts(plant, upright);
	std::array<Regrowth, FieldMap::MAX_SPECIES> regrowth{};
	regrowth[0].flattened_seconds = 10.0;
	sim.set_regrowth(regrowth);
	std::vector<uint32_t> changed;
	sim.change_cells({ near_cell }, FieldSimulation::CellAction::FLATTEN, 5.0, changed);
	REQUIRE(changed.size() == 1);
	sim.update(0.016f);
	PartTransforms lying;
	sim.near().get_plant_parts(plant, lying);
	const glm::vec3 root = sim.plants().get_layout().plants[plant].root();
	const auto lean = [&](const PartTransforms &p_parts) {
		return glm::length(glm::vec2(p_parts.origin[2].x - root.x, p_parts.origin[2].z - root.z));
	};
	CHECK(lean(lying) > lean(upright) + 0.3f); // its head well away from above its root
	CHECK(drawn_at(sim, root, false) == 1); // drawn near, lying
	// An impostor of an active chunk: not drawn (an impostor would stand it up).
	const uint32_t middle_cell = cell(55, 35);
	const uint32_t middle = sim.plants().plant_at_cell(middle_cell);
	REQUIRE(sim.near().is_chunk_active(sim.plants().get_layout().plants[middle].chunk));
	REQUIRE(sim.near().get_plant_lod(middle) >= LOD_SPRITE);
	const glm::vec3 middle_root = sim.plants().get_layout().plants[middle].root();
	CHECK(drawn_at(sim, middle_root, false) == 1);
	sim.change_cells({ middle_cell }, FieldSimulation::CellAction::FLATTEN, 5.0, changed);
	sim.update(0.016f);
	CHECK(drawn_at(sim, middle_root, false) == 0);
	std::vector<uint32_t> recovered;
	sim.advance_changes(14.9, recovered);
	CHECK(recovered.empty());
	sim.advance_changes(15.0, recovered);
	CHECK(recovered == std::vector<uint32_t>{ near_cell, middle_cell });
	CHECK(sim.plants().get_plant_state(plant) == PlantState::STANDING);
	sim.update(0.016f);
	PartTransforms standing;
	sim.near().get_plant_parts(plant, standing);
	CHECK(lean(standing) < lean(lying) - 0.3f);
}

TEST_CASE("play: a save loads back into the simulation, drawn at once; a bad one changes nothing") {
	FieldSimulation sim;
	load(sim, rect_map(200, 40));
	sim.near().set_observer({ 5.0f, 1.7f, 5.0f });
	sim.update(0.016f);
	std::vector<uint32_t> changed;
	sim.change_cells({ cell(10, 10), cell(12, 10) }, FieldSimulation::CellAction::REMOVE, 1.0, changed);
	sim.change_cells({ cell(14, 10) }, FieldSimulation::CellAction::CUT, 2.0, changed);
	const std::vector<uint8_t> saved = sim.save_changes(3.0);
	sim.change_cells({ cell(10, 10), cell(12, 10), cell(14, 10) }, FieldSimulation::CellAction::RESTORE, 4.0, changed);
	sim.change_cells({ cell(20, 20) }, FieldSimulation::CellAction::CUT, 4.0, changed);
	sim.update(0.016f);
	const glm::vec3 root = sim.plants().get_layout().plants[sim.plants().plant_at_cell(cell(12, 10))].root();
	CHECK(drawn_at(sim, root, false) == 1);
	double clock = 0.0;
	CHECK(sim.load_changes(saved, clock) == "");
	CHECK(clock == 3.0);
	sim.update(0.016f);
	CHECK(drawn_at(sim, root, false) == 0);
	CHECK(sim.plants().get_plant_state(sim.plants().plant_at_cell(cell(20, 20))) == PlantState::STANDING);
	CHECK(sim.changes().changes().size() == 3);
	std::vector<uint8_t> corrupt = saved;
	corrupt[corrupt.size() / 2] ^= 1;
	CHECK(sim.load_changes(corrupt, clock).find("corrupt") != std::string::npos);
	CHECK(sim.changes().changes().size() == 3);
}

TEST_CASE("play: pushers trample the standing plants within their share of the radius, each once") {
	FieldSimulation sim;
	load(sim, rect_map(200, 40));
	sim.near().set_observer({ 5.0f, 1.7f, 5.0f });
	sim.update(0.016f);
	for (uint32_t plant = 0; plant < sim.plants().get_plant_count(); plant += 97) {
		CHECK(sim.plants().plant_at_cell(sim.plants().cell_of_plant(plant)) == plant);
	}
	CHECK(sim.plants().cell_of_plant(sim.plants().get_plant_count()) == FieldPlants::NO_CELL);

	const Pusher pushers[2] = { { { 10.0f, 0.5f, 10.0f }, 1.0f }, { { 10.4f, 0.5f, 10.0f }, 1.0f } };
	sim.near().get_pushes().set_pushers(pushers, 2);
	std::vector<FieldSimulation::Trampled> trampled;
	sim.trample(0.0f, 1.0, trampled);
	CHECK(trampled.empty()); // share 0: pushers only bend plants
	sim.trample(0.5f, 1.0, trampled);
	REQUIRE(!trampled.empty());
	std::vector<uint32_t> cells;
	for (const FieldSimulation::Trampled &each : trampled) {
		const uint32_t plant = sim.plants().plant_at_cell(each.cell);
		REQUIRE(plant != FieldPlants::NO_PLANT);
		const glm::vec2 root = sim.plants().get_layout().plants[plant].position;
		CHECK(glm::distance(root, glm::vec2(pushers[each.pusher].position.x, pushers[each.pusher].position.z)) < 0.5f);
		CHECK(sim.get_cell_state(each.cell).state == PlantState::FLATTENED);
		CHECK(sim.get_cell_state(each.cell).since == 1.0);
		cells.push_back(each.cell);
	}
	std::sort(cells.begin(), cells.end());
	CHECK(std::unique(cells.begin(), cells.end()) == cells.end()); // each plant once, by one pusher
	// Every standing plant within reach of either pusher was trampled.
	std::vector<uint32_t> near;
	for (const Pusher &pusher : pushers) {
		sim.plants().find_plants_near(glm::vec2(pusher.position.x, pusher.position.z), 0.5f, near);
	}
	std::sort(near.begin(), near.end());
	near.erase(std::unique(near.begin(), near.end()), near.end());
	CHECK(near.size() == cells.size());
	// Again: they lie already, nothing new.
	trampled.clear();
	sim.trample(0.5f, 2.0, trampled);
	CHECK(trampled.empty());
	// A pusher above the plants' heads tramples nothing.
	const Pusher high{ { 30.0f, 40.0f, 10.0f }, 1.0f };
	sim.near().get_pushes().set_pushers(&high, 1);
	sim.trample(1.0f, 3.0, trampled);
	CHECK(trampled.empty());
}

TEST_CASE("play: the far tiles never change; the hidden-cells mask hides exactly the plants play took down") {
	FieldSimulation sim;
	load(sim, rect_map(200, 40));
	CHECK(sim.get_hidden_cells().empty()); // nothing until the first change
	std::vector<std::vector<float>> before(sim.tiles().get_tile_count());
	for (uint32_t t = 0; t < sim.tiles().get_tile_count(); ++t) {
		before[t].resize(size_t(sim.tiles().get_tile(t).plants) * FAR_FLOATS_PER_INSTANCE);
		sim.tiles().write_tile_instances(t, before[t].data());
	}
	std::vector<uint32_t> cut;
	cells_in_circle(200, 40, 0.5f, glm::vec2(70.0f, 10.0f), 3.0f, cut);
	std::vector<uint32_t> flat = { cell(3, 3), cell(199, 39) };
	std::vector<uint32_t> changed;
	const uint32_t version = sim.get_hidden_version();
	sim.change_cells(cut, FieldSimulation::CellAction::CUT, 1.0, changed);
	sim.change_cells(flat, FieldSimulation::CellAction::FLATTEN, 1.0, changed);
	sim.change_cells({ cell(4, 3) }, FieldSimulation::CellAction::REMOVE, 1.0, changed);
	REQUIRE(changed.size() == cut.size() + 3);
	CHECK(sim.get_hidden_version() != version);
	CHECK(sim.hidden_row_bytes() == 25);
	REQUIRE(sim.get_hidden_cells().size() == size_t(25 * 40));
	// The tiles' records are as before, and every plant's cell from its root (as the impostor shader
	// finds it) is hidden exactly when play took the plant down.
	size_t hidden = 0;
	size_t wrong = 0;
	for (uint32_t t = 0; t < sim.tiles().get_tile_count(); ++t) {
		std::vector<float> now(before[t].size());
		sim.tiles().write_tile_instances(t, now.data());
		CHECK(now == before[t]);
		for (size_t k = 0; k < sim.tiles().get_tile(t).plants; ++k) {
			const FarInstance record = read_far_instance(now.data() + k * FAR_FLOATS_PER_INSTANCE);
			const int column = int(std::floor(record.root.x / 0.5f + 0.25f));
			const int row = int(std::floor(record.root.z / 0.5f + 0.25f));
			const bool bit = (sim.get_hidden_cells()[size_t(row) * 25 + size_t(column / 8)] >> (column % 8)) & 1;
			const uint32_t own = cell(column, row);
			const bool taken = sim.plants().get_plant_state(sim.plants().plant_at_cell(own)) != PlantState::STANDING;
			wrong += bit != taken ? 1 : 0;
			hidden += bit ? 1 : 0;
		}
	}
	CHECK(wrong == 0);
	CHECK(hidden >= cut.size() + 3); // (merged levels hold some plants twice)
	// Standing again: its bit goes.
	changed.clear();
	sim.change_cells(flat, FieldSimulation::CellAction::STAND, 2.0, changed);
	CHECK(((sim.get_hidden_cells()[3 * 25] >> 3) & 1) == 0);
	CHECK(((sim.get_hidden_cells()[39 * 25 + 24] >> 7) & 1) == 0);
	CHECK(((sim.get_hidden_cells()[3 * 25] >> 4) & 1) == 1); // (the removed one stays hidden)
}

TEST_CASE("play: a plant put in an empty cell, or of another type, is drawn at every distance at once; restored, it goes") {
	// 200 × 40 cells of '*' (species 0) with empty rows 20 and 21, and an 'm' (species 1) at (150, 5).
	std::string text = "200 40\n";
	for (int row = 0; row < 40; ++row) {
		std::string line(200, row == 20 || row == 21 ? '.' : '*');
		if (row == 5) {
			line[150] = 'm';
		}
		text += line + "\n";
	}
	FieldSimulation sim;
	MapError error;
	REQUIRE(sim.load_map(text, U"m", U"m", "put", MapLimits{}, error));
	LayoutParams params;
	params.chunk_size = 8.0f;
	sim.set_layout_params(params);
	sim.near().set_observer({ 5.0f, 1.7f, 10.0f });
	sim.near().request_lod_update();
	sim.update(0.016f);
	const uint32_t map_plants = sim.plants().get_plant_count();
	const uint32_t map_chunks = sim.plants().get_chunk_count();
	const uint32_t records_version = sim.get_records_version();
	const uint32_t near_empty = cell(12, 20); // about 7 m off: a mesh
	const uint32_t far_empty = cell(190, 21); // about 93 m off: where only far tiles draw
	const uint32_t far_other = cell(180, 30); // a '*' to become an 'm', far
	const uint32_t near_other = cell(8, 12); // a '*' to become an 'm', near
	REQUIRE(sim.plants().plant_at_cell(near_empty) == FieldPlants::NO_PLANT);
	const glm::vec3 far_other_root = sim.plants().get_layout().plants[sim.plants().plant_at_cell(far_other)].root();
	CHECK(drawn_at(sim, far_other_root, true) >= 1);

	std::vector<uint32_t> changed;
	sim.put_cells({ near_empty, far_empty, far_other, near_other, near_other }, 1, changed);
	CHECK(changed == std::vector<uint32_t>{ near_empty, far_empty, far_other, near_other }); // the second put is none
	CHECK(sim.get_records_version() == records_version); // no rebuild, no tile written
	CHECK(sim.plants().get_map_plant_count() == map_plants);
	CHECK(sim.plants().get_plant_count() == map_plants + 4); // appended: no map plant's index moved
	CHECK(sim.plants().get_map_chunk_count() == map_chunks);
	sim.update(0.016f);
	for (uint32_t put : changed) {
		const uint32_t plant = sim.plants().added_plant_at_cell(put);
		REQUIRE(plant != FieldPlants::NO_PLANT);
		CHECK(plant >= map_plants);
		CHECK(sim.plants().cell_of_plant(plant) == put);
		const Plant &added = sim.plants().get_layout().plants[plant];
		CHECK(sim.plants().species_of(added) == 1);
		// Where the layout would lay out a plant of that cell: the randomness follows the cell.
		CHECK(added.position == plant_root_at(sim.plants().get_map(), sim.plants().get_layout_params(), int(put % 200), int(put / 200)));
		CHECK(sim.near().is_chunk_active(added.chunk));
		CHECK(drawn_at(sim, added.root(), true) == 1); // once: near or as a near impostor, never twice
		CHECK(sim.get_cell_state(put).plant == 2);
	}
	CHECK(sim.near().get_plant_lod(sim.plants().added_plant_at_cell(near_empty)) <= LOD_MESH_2);
	CHECK(sim.near().get_plant_lod(sim.plants().added_plant_at_cell(far_empty)) >= LOD_SPRITE);
	// The map's plant of a cell given another type is hidden everywhere (its far record by the mask).
	CHECK(drawn_at(sim, far_other_root, true) == 1); // the added 'm' alone (it stands where the '*' stood)
	CHECK(sim.plants().get_plant_state(sim.plants().plant_at_cell(far_other)) == PlantState::GONE);
	CHECK(hidden_at(sim, far_other_root));
	// The far tiles' active mask does not take the added plants' chunks for the map's: an 'm' put
	// beside the map's far 'm' leaves that one to its far tile.
	const glm::vec3 map_m_root = sim.plants().get_layout().plants[sim.plants().plant_at_cell(cell(150, 5))].root();
	CHECK(drawn_at(sim, map_m_root, true) == 1);
	changed.clear();
	sim.put_cells({ cell(151, 5) }, 1, changed);
	sim.update(0.016f);
	CHECK(drawn_at(sim, map_m_root, true) == 1);
	std::vector<uint8_t> active(size_t(sim.plants().get_layout().grid_x) * size_t(sim.plants().get_layout().grid_z));
	sim.near().write_active_mask(1, active.data());
	const uint32_t map_m_chunk = sim.plants().get_layout().plants[sim.plants().plant_at_cell(cell(150, 5))].chunk;
	CHECK(active[sim.plants().get_chunk_cell(map_m_chunk)] == 0);
	changed.clear();
	sim.change_cells({ cell(151, 5) }, FieldSimulation::CellAction::RESTORE, 1.0, changed);
	// Queries find the added plants; they can be trampled, cut, and restored.
	std::vector<uint32_t> near;
	const glm::vec3 near_root = sim.plants().get_layout().plants[sim.plants().added_plant_at_cell(near_empty)].root();
	sim.plants().find_plants_near(glm::vec2(near_root.x, near_root.z), 0.1f, near);
	CHECK(near == std::vector<uint32_t>{ sim.plants().added_plant_at_cell(near_empty) });
	changed.clear();
	sim.change_cells({ near_empty }, FieldSimulation::CellAction::CUT, 2.0, changed);
	sim.update(0.016f);
	CHECK(drawn_at(sim, near_root, false) == 0);
	changed.clear();
	sim.change_cells({ near_empty, far_other }, FieldSimulation::CellAction::RESTORE, 3.0, changed);
	CHECK(changed.size() == 2);
	sim.update(0.016f);
	CHECK(drawn_at(sim, near_root, true) == 0);
	CHECK(sim.plants().added_plant_at_cell(near_empty) == FieldPlants::NO_PLANT);
	CHECK(sim.plants().cell_of_plant(map_plants) == FieldPlants::NO_CELL);
	// Sowing and harvesting again and again uses the slots of the plants taken: the field does not grow.
	const uint32_t slots = sim.plants().get_plant_count();
	for (int round = 0; round < 3; ++round) {
		changed.clear();
		sim.put_cells({ near_empty, cell(13, 20) }, 1, changed);
		sim.update(0.016f);
		CHECK(drawn_at(sim, near_root, false) == 1);
		sim.change_cells({ near_empty, cell(13, 20) }, FieldSimulation::CellAction::RESTORE, 3.0, changed);
	}
	CHECK(sim.plants().get_plant_count() == slots);
	near.clear();
	sim.plants().find_plants_near(glm::vec2(near_root.x, near_root.z), 0.1f, near);
	CHECK(near.empty());
	CHECK(drawn_at(sim, far_other_root, true) >= 1); // the map's '*' back, as a far record
	CHECK_FALSE(hidden_at(sim, far_other_root));

	// A layout rebuilt for the same map adds them again; every plant is drawn exactly once.
	params.chunk_size = 4.0f;
	REQUIRE(sim.set_layout_params(params));
	sim.near().request_lod_update();
	sim.update(0.016f);
	CHECK(sim.plants().get_plant_count() == sim.plants().get_map_plant_count() + 2);
	const uint32_t far_put = sim.plants().added_plant_at_cell(far_empty);
	REQUIRE(far_put != FieldPlants::NO_PLANT);
	CHECK(drawn_at(sim, sim.plants().get_layout().plants[far_put].root(), true) == 1);
	CHECK(total(sim.near().get_lod_counts()) == int64_t(sim.plants().get_plant_count()));

	// The map's own type put back in a cell whose plant was removed stands it again, as the map has it.
	changed.clear();
	sim.change_cells({ cell(30, 30) }, FieldSimulation::CellAction::REMOVE, 4.0, changed);
	sim.put_cells({ cell(30, 30) }, 0, changed);
	CHECK(changed.size() == 2);
	CHECK_FALSE(sim.changes().is_changed(cell(30, 30)));
}

TEST_CASE("play: a plant put where the ground is not known waits for a height, then stands on it") {
	FieldSimulation sim;
	load(sim, "4 1\n*..*\n");
	Ground ground;
	ground.kind = Ground::HEIGHTS;
	ground.heights = { 1.0f, 2.0f }; // the two map plants' ground points
	sim.set_ground(ground);
	std::vector<uint32_t> changed;
	sim.put_cells({ 0, 1 }, 0, changed);
	CHECK(changed == std::vector<uint32_t>{ 1 }); // (cell 0 holds a '*' already)
	CHECK(sim.get_unplaced_cells() == std::vector<uint32_t>{ 1 });
	CHECK(sim.plants().added_plant_at_cell(1) == FieldPlants::NO_PLANT);
	sim.set_cell_heights({ 1 }, { 1.5f });
	CHECK(sim.get_unplaced_cells().empty());
	const uint32_t plant = sim.plants().added_plant_at_cell(1);
	REQUIRE(plant != FieldPlants::NO_PLANT);
	CHECK(sim.plants().get_layout().plants[plant].ground == 1.5f);
	sim.update(0.016f);
	CHECK(drawn_at(sim, sim.plants().get_layout().plants[plant].root(), false) == 1);
}

TEST_CASE("play: a cut plant leaves the stump its type says, part by part or drawn whole; a removed one none") {
	for (const bool whole : { false, true }) {
		FieldSimulation sim;
		load(sim, rect_map(200, 40));
		PlantShape shape = sim.plants().get_shape(0);
		shape.whole = whole;
		sim.set_shape(shape);
		sim.set_plant_height(2.0f);
		sim.near().set_stump_height(0, 0.3f);
		sim.near().set_observer({ 5.0f, 1.7f, 5.0f });
		sim.near().request_lod_update();
		sim.update(0.016f);
		const uint32_t cut_cell = cell(10, 10);
		const uint32_t removed_cell = cell(12, 10);
		const glm::vec3 cut_root = sim.plants().get_layout().plants[sim.plants().plant_at_cell(cut_cell)].root();
		const glm::vec3 removed_root = sim.plants().get_layout().plants[sim.plants().plant_at_cell(removed_cell)].root();
		std::vector<uint32_t> changed;
		sim.change_cells({ cut_cell }, FieldSimulation::CellAction::CUT, 1.0, changed);
		sim.change_cells({ removed_cell }, FieldSimulation::CellAction::REMOVE, 1.0, changed);
		sim.update(0.016f);
		const PlantShape &drawn = sim.plants().get_shape(0);
		const float size = drawn.part_scale * sim.plants().get_layout().plants[sim.plants().plant_at_cell(cut_cell)].scale;
		int stumps = 0;
		int others = 0;
		for (uint32_t level = 0; level < LOD_MESH_COUNT; ++level) {
			for (uint32_t part = 0; part < PART_COUNT; ++part) {
				const InstanceBuffer &bucket = sim.near().get_bucket(mesh_bucket(level, part));
				for (uint32_t i = 0; i < bucket.get_count(); ++i) {
					const float *instance = bucket.get_data() + size_t(i) * bucket.get_stride();
					const glm::vec3 root = placed(bucket, i).root;
					others += glm::distance(root, removed_root) < 1e-4f ? 1 : 0;
					if (glm::distance(root, cut_root) > 1e-4f) {
						continue;
					}
					++stumps;
					CHECK(part == 0);
					if (whole) {
						CHECK(read_whole_instance(instance).middle == doctest::Approx(-0.3f / size)); // model units
					} else {
						// The bottom part's up axis, shortened: its length times the part's model length.
						const glm::vec3 up(instance[1], instance[5], instance[9]);
						CHECK(glm::length(up) * drawn.part_lengths[0] == doctest::Approx(0.3f).epsilon(1e-3));
						CHECK(up.y > 0.999f * glm::length(up)); // upright
					}
				}
			}
		}
		CHECK(stumps == 1);
		CHECK(others == 0); // a removed plant leaves nothing
		// A plant of one part has no bottom part of its own to leave.
		shape.part_lengths = glm::vec3(1.0f, 0.0f, 0.0f);
		sim.set_shape(shape);
		sim.update(0.016f);
		stumps = 0;
		for (uint32_t level = 0; level < LOD_MESH_COUNT; ++level) {
			const InstanceBuffer &bucket = sim.near().get_bucket(mesh_bucket(level, 0));
			for (uint32_t i = 0; i < bucket.get_count(); ++i) {
				stumps += glm::distance(placed(bucket, i).root, cut_root) < 1e-4f ? 1 : 0;
			}
		}
		CHECK(stumps == 0);
	}
}
