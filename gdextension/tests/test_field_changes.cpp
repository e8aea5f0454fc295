// Core tests of what play changes in a field: states, regrowth, saves, against a reference model.
#include "field_changes.h"
#include "random_hash.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace sunflower;

namespace {

// A map of p_columns × p_rows cells: '*' where (column + row) % 3 != 0, species 1 where it is 0 and
// the column is even, else empty; two species.
FieldMap striped(int p_columns, int p_rows) {
	FieldMap map;
	map.columns = p_columns;
	map.rows = p_rows;
	map.species_count = 2;
	for (int row = 0; row < p_rows; row++) {
		for (int column = 0; column < p_columns; column++) {
			const bool plant = (column + row) % 3 != 0;
			map.plants.push_back(plant ? 1 : (column % 2 == 0 ? 2 : 0));
			map.plant_count += map.plants.back() != 0 ? 1 : 0;
		}
	}
	return map;
}

uint32_t cell(const FieldMap &p_map, int p_column, int p_row) {
	return static_cast<uint32_t>(p_row * p_map.columns + p_column);
}

} // namespace

TEST_CASE("field changes: cut, flatten, remove and put hold only what differs from the map") {
	const FieldMap map = striped(12, 9);
	FieldChanges changes;
	changes.reset(map);
	const uint32_t sunflower = cell(map, 1, 0);
	const uint32_t empty = cell(map, 3, 0); // (3 + 0) % 3 == 0, odd column: no plant
	REQUIRE(changes.get(sunflower).plant == 1);
	REQUIRE(changes.get(empty).plant == 0);
	CHECK(changes.set_state(sunflower, PlantState::FLATTENED, 2.0));
	CHECK_FALSE(changes.set_state(sunflower, PlantState::FLATTENED, 3.0)); // already lying
	CHECK(changes.get(sunflower).since == 2.0);
	CHECK(changes.set_state(sunflower, PlantState::CUT, 4.0));
	CHECK_FALSE(changes.set_state(sunflower, PlantState::FLATTENED, 5.0)); // nothing standing to flatten
	CHECK(changes.get(sunflower).state == PlantState::CUT);
	CHECK_FALSE(changes.set_state(empty, PlantState::CUT, 1.0)); // no plant to cut
	CHECK(changes.changes().size() == 1);
	// Standing again as the map has it: no change held.
	CHECK(changes.set_state(sunflower, PlantState::STANDING, 6.0));
	CHECK_FALSE(changes.is_changed(sunflower));
	// Removed, then the map's plant put back: the same.
	CHECK(changes.remove(sunflower));
	CHECK_FALSE(changes.remove(sunflower));
	CHECK(changes.get(sunflower).plant == 0);
	CHECK(changes.put(sunflower, 0));
	CHECK_FALSE(changes.is_changed(sunflower));
	// A plant put where the map has none; another type over a sunflower; no type the map lacks.
	CHECK(changes.put(empty, 1));
	CHECK(changes.get(empty).plant == 2);
	CHECK(changes.put(sunflower, 1));
	CHECK_FALSE(changes.put(sunflower, 2));
	CHECK_FALSE(changes.put(sunflower, -1));
	CHECK_FALSE(changes.put(static_cast<uint32_t>(map.plants.size()), 0)); // past the map
	CHECK(changes.changes().size() == 2);
	CHECK(changes.restore(empty));
	CHECK(changes.get(empty).plant == 0);
	CHECK(changes.changes().size() == 1);
	CHECK_FALSE(changes.set_state(sunflower, PlantState::CUT, NAN));
}

TEST_CASE("field changes: a flattened plant stands again and a cut one regrows when their type says") {
	const FieldMap map = striped(12, 9);
	FieldChanges changes;
	changes.reset(map);
	std::array<Regrowth, FieldMap::MAX_SPECIES> regrowth{};
	regrowth[0] = Regrowth{ 5.0, 30.0 }; // sunflowers
	regrowth[1] = Regrowth{ 0.0, 0.0 }; // species 1 never recovers
	changes.set_regrowth(regrowth);
	const uint32_t a = cell(map, 1, 0);
	const uint32_t b = cell(map, 2, 0);
	const uint32_t never = cell(map, 0, 0); // species 1
	REQUIRE(changes.get(never).plant == 2);
	changes.set_state(a, PlantState::FLATTENED, 10.0);
	changes.set_state(b, PlantState::CUT, 10.0);
	changes.set_state(never, PlantState::FLATTENED, 10.0);
	std::vector<uint32_t> recovered;
	changes.advance(14.999, recovered);
	CHECK(recovered.empty());
	changes.advance(15.0, recovered);
	REQUIRE(recovered == std::vector<uint32_t>{ a });
	CHECK_FALSE(changes.is_changed(a));
	// Trampled again before it stands: the recovery counts from the last time.
	recovered.clear();
	changes.set_state(a, PlantState::FLATTENED, 16.0);
	changes.set_state(a, PlantState::STANDING, 17.0);
	changes.set_state(a, PlantState::FLATTENED, 18.0);
	changes.advance(22.0, recovered);
	CHECK(recovered.empty()); // the first flattening's time is stale
	changes.advance(23.0, recovered);
	CHECK(recovered == std::vector<uint32_t>{ a });
	recovered.clear();
	changes.advance(39.9, recovered);
	CHECK(recovered.empty());
	changes.advance(40.0, recovered);
	CHECK(recovered == std::vector<uint32_t>{ b });
	recovered.clear();
	changes.advance(1.0e9, recovered);
	CHECK(recovered.empty());
	CHECK(changes.get(never).state == PlantState::FLATTENED);
	// A new timing applies to plants lying already.
	regrowth[1].flattened_seconds = 1.0;
	changes.set_regrowth(regrowth);
	changes.advance(1.0e9, recovered);
	CHECK(recovered == std::vector<uint32_t>{ never });
}

TEST_CASE("field changes: a save loads back cell for cell, with its clock") {
	const FieldMap map = striped(40, 30);
	FieldChanges changes;
	changes.reset(map);
	for (uint32_t i = 0; i < 1200; i += 7) {
		switch (i % 4) {
			case 0:
				changes.set_state(i, PlantState::FLATTENED, 0.25 * i);
				break;
			case 1:
				changes.set_state(i, PlantState::CUT, 100.0 + i);
				break;
			case 2:
				changes.remove(i);
				break;
			default:
				changes.put(i, 1);
		}
	}
	REQUIRE(changes.changes().size() > 100);
	const std::vector<uint8_t> saved = changes.save(2000.0);
	FieldChanges loaded;
	loaded.reset(map);
	double clock = 0.0;
	CHECK(loaded.load(saved, clock) == "");
	CHECK(clock == 2000.0);
	REQUIRE(loaded.changes().size() == changes.changes().size());
	for (const auto &[at, state] : changes.changes()) {
		const CellState other = loaded.get(at);
		CHECK(other.plant == state.plant);
		CHECK(other.state == state.state);
		CHECK(std::abs(other.since - state.since) <= 0.0005); // kept to the millisecond
	}
	CHECK(loaded.save(2000.0) == saved);
}

TEST_CASE("field changes: a corrupt save, another map's, or a newer version's is refused and changes nothing") {
	const FieldMap map = striped(40, 30);
	FieldChanges changes;
	changes.reset(map);
	changes.set_state(cell(map, 1, 1), PlantState::CUT, 3.0);
	changes.remove(cell(map, 2, 2));
	const std::vector<uint8_t> saved = changes.save(10.0);
	FieldChanges target;
	target.reset(map);
	target.put(cell(map, 3, 3), 0);
	const std::map<uint32_t, CellState> before = target.changes();
	double clock = -1.0;
	// Every single byte flipped: refused, naming why.
	for (size_t i = 0; i < saved.size(); i++) {
		std::vector<uint8_t> bad = saved;
		bad[i] ^= 0x10;
		const std::string error = target.load(bad, clock);
		CHECK_MESSAGE(!error.empty(), "byte " << i << " flipped");
	}
	std::vector<uint8_t> cut_short(saved.begin(), saved.end() - 6);
	CHECK(target.load(cut_short, clock).find("corrupt") != std::string::npos);
	CHECK(target.load({}, clock).find("SFCH") != std::string::npos);
	// Another map: another size, or the same size with other plants.
	FieldChanges smaller;
	smaller.reset(striped(20, 30));
	CHECK(smaller.load(saved, clock) == "the save was made on a map of 40 x 30 cells; this field's map has 20 x 30");
	FieldMap other = map;
	other.plants[5] = 0;
	FieldChanges changed_map;
	changed_map.reset(other);
	CHECK(changed_map.load(saved, clock).find("another map") != std::string::npos);
	// A newer version's save.
	std::vector<uint8_t> newer = saved;
	newer[4] = 2;
	CHECK(target.load(newer, clock).find("version 2") != std::string::npos);
	CHECK(target.changes().size() == before.size());
	CHECK(target.get(cell(map, 3, 3)).plant == 1);
	CHECK(clock == -1.0);
}

TEST_CASE("field changes: 10 000 changes in a million-plant field save in under 100 KB") {
	FieldMap map;
	map.columns = 1000;
	map.rows = 1000;
	map.plants.assign(1000000, 1);
	map.plant_count = 1000000;
	FieldChanges changes;
	changes.reset(map);
	int made = 0;
	for (uint64_t i = 0; made < 10000; i++) {
		const uint32_t at = static_cast<uint32_t>(hash_plant(5, i, 1) % 1000000);
		const PlantState state = (i % 2) ? PlantState::CUT : PlantState::FLATTENED;
		made += changes.set_state(at, state, 3600.0 * unit_float(hash_plant(5, i, 2))) ? 1 : 0;
	}
	const std::vector<uint8_t> saved = changes.save(7200.0);
	MESSAGE("10 000 changes saved in " << saved.size() << " bytes");
	CHECK(saved.size() <= 100000);
}

TEST_CASE("field changes: circles and rectangles of cells") {
	std::vector<uint32_t> cells;
	cells_in_circle(20, 10, 0.5f, glm::vec2(2.0f, 2.0f), 1.0f, cells); // 4 cells of radius around (4, 4)
	for (uint32_t at : cells) {
		const float dx = (float(at % 20) + 0.5f) * 0.5f - 2.0f;
		const float dz = (float(at / 20) + 0.5f) * 0.5f - 2.0f;
		CHECK(dx * dx + dz * dz <= 1.0f);
	}
	CHECK(cells.size() == 12); // the cells whose centres lie within two cells' length of a corner
	cells.clear();
	cells_in_rect(20, 10, 0.5f, glm::vec2(1.0f, 0.0f), glm::vec2(2.0f, 0.5f), cells); // columns 2–3, row 0
	CHECK(cells == std::vector<uint32_t>{ 2, 3 });
	cells.clear();
	cells_in_circle(20, 10, 0.5f, glm::vec2(-50.0f, 0.0f), 3.0f, cells);
	cells_in_circle(20, 10, 0.5f, glm::vec2(NAN, 0.0f), 3.0f, cells);
	cells_in_rect(20, 10, 0.5f, glm::vec2(5.0f, 5.0f), glm::vec2(1.0f, 1.0f), cells);
	CHECK(cells.empty());
}

TEST_CASE("field changes: any sequence of changes agrees with a plain model of every cell") {
	const FieldMap map = striped(16, 12);
	const size_t count = map.plants.size();
	std::array<Regrowth, FieldMap::MAX_SPECIES> regrowth{};
	regrowth[0] = Regrowth{ 3.0, 7.0 };
	regrowth[1] = Regrowth{ 0.0, 5.0 };
	FieldChanges changes;
	changes.reset(map);
	changes.set_regrowth(regrowth);
	// The model: every cell's plant, state and since, recovered by scanning every cell.
	std::vector<CellState> model(count);
	for (size_t i = 0; i < count; i++) {
		model[i].plant = map.plants[i];
	}
	double now = 0.0;
	for (uint64_t step = 0; step < 20000; step++) {
		const uint64_t h = hash_plant(9, step, 3);
		const uint32_t at = static_cast<uint32_t>(h % count);
		CellState &m = model[at];
		switch ((h >> 20) % 6) {
			case 0:
			case 1: {
				const PlantState state = static_cast<PlantState>((h >> 24) % 3);
				const bool can = m.plant != 0 && m.state != state && !(m.state == PlantState::CUT && state == PlantState::FLATTENED);
				CHECK(changes.set_state(at, state, now) == can);
				if (can) {
					m.state = state;
					m.since = state == PlantState::STANDING ? 0.0 : now;
				}
				break;
			}
			case 2:
				CHECK(changes.remove(at) == (m.plant != 0));
				m = CellState{};
				break;
			case 3: {
				const int species = static_cast<int>((h >> 24) % 3); // 2 is not a species of the map
				const bool can = species < 2 && !(m.plant == species + 1 && m.state == PlantState::STANDING);
				CHECK(changes.put(at, species) == can);
				if (can) {
					m = CellState{};
					m.plant = static_cast<uint8_t>(species + 1);
				}
				break;
			}
			case 4: {
				now += 0.37 * double((h >> 24) % 8);
				std::vector<uint32_t> recovered;
				changes.advance(now, recovered);
				size_t expected = 0;
				for (CellState &c : model) {
					if (c.plant == 0 || c.state == PlantState::STANDING) {
						continue;
					}
					const Regrowth &r = regrowth[c.plant - 1];
					const double seconds = c.state == PlantState::FLATTENED ? r.flattened_seconds : r.cut_seconds;
					if (seconds > 0.0 && c.since + seconds <= now) {
						c.state = PlantState::STANDING;
						c.since = 0.0;
						expected++;
					}
				}
				CHECK(recovered.size() == expected);
				break;
			}
			default: {
				// A save and a load midway change nothing.
				FieldChanges again;
				again.reset(map);
				again.set_regrowth(regrowth);
				double clock = 0.0;
				REQUIRE(again.load(changes.save(now), clock) == "");
				for (size_t i = 0; i < count; i++) {
					const CellState a = again.get(static_cast<uint32_t>(i));
					const CellState b = changes.get(static_cast<uint32_t>(i));
					REQUIRE(a.plant == b.plant);
					REQUIRE(a.state == b.state);
				}
			}
		}
		if (step % 500 == 0) {
			for (size_t i = 0; i < count; i++) {
				const CellState got = changes.get(static_cast<uint32_t>(i));
				REQUIRE(got.plant == model[i].plant);
				REQUIRE(got.state == model[i].state);
				REQUIRE(got.since == model[i].since);
				REQUIRE(changes.is_changed(static_cast<uint32_t>(i)) ==
						(model[i].plant != map.plants[i] || model[i].state != PlantState::STANDING));
			}
		}
	}
}
