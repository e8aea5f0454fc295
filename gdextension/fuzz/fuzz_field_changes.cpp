// libFuzzer target: sequences of play's changes (field_changes.h through FieldSimulation) checked
// against a plain reference model after every step: stand, flatten, cut, remove, restore, put and
// trample by cells (each plant of another type than the map's an added plant of that type); regrowth on the clock (its timings changed midway too); saves loaded back into a
// fresh simulation cell for cell, a save with one bit flipped and one of another map refused with
// nothing changed; the hidden-cells mask in step with the plants' states. Under ASan + UBSan; any
// crash, sanitizer report or difference from the model is a finding.
#include "field_simulation.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

using namespace sunflower;

namespace {

// Reads the input a byte at a time; zeros once it is used up.
struct Input {
	const uint8_t *data;
	size_t size;
	size_t at = 0;
	bool more() const { return at < size; }
	uint8_t next() { return at < size ? data[at++] : 0; }
};

// What a cell holds, kept the plain way: the model the simulation's changes must match.
struct Model {
	std::vector<CellState> cells;
	std::vector<uint8_t> map;
	std::array<Regrowth, FieldMap::MAX_SPECIES> regrowth{};

	bool set_state(uint32_t p_cell, PlantState p_state, double p_now) {
		CellState &cell = cells[p_cell];
		if (cell.plant == 0 || cell.state == p_state || (cell.state == PlantState::CUT && p_state == PlantState::FLATTENED)) {
			return false;
		}
		cell.state = p_state;
		cell.since = p_state == PlantState::STANDING ? 0.0 : p_now;
		return true;
	}
	bool remove(uint32_t p_cell) {
		if (cells[p_cell].plant == 0) {
			return false;
		}
		cells[p_cell] = CellState{};
		return true;
	}
	bool put(uint32_t p_cell, uint8_t p_species) {
		const CellState put{ uint8_t(p_species + 1), PlantState::STANDING, 0.0 };
		const bool changed = !(cells[p_cell] == put);
		cells[p_cell] = put;
		return changed;
	}
	bool restore(uint32_t p_cell) {
		const CellState as_map{ map[p_cell], PlantState::STANDING, 0.0 };
		const bool changed = !(cells[p_cell] == as_map);
		cells[p_cell] = as_map;
		return changed;
	}
	void advance(double p_now, std::vector<uint32_t> &r_recovered) {
		for (uint32_t c = 0; c < cells.size(); ++c) {
			CellState &cell = cells[c];
			if (cell.plant == 0 || cell.state == PlantState::STANDING) {
				continue;
			}
			const Regrowth &timing = regrowth[cell.plant - 1];
			const double seconds = cell.state == PlantState::FLATTENED ? timing.flattened_seconds : timing.cut_seconds;
			if (seconds > 0.0 && cell.since + seconds <= p_now) {
				cell = CellState{ cell.plant, PlantState::STANDING, 0.0 };
				r_recovered.push_back(c);
			}
		}
	}
};

void check(bool p_condition) {
	if (!p_condition) {
		std::abort();
	}
}

// Every cell of the simulation as the model has it, and its hidden bit set exactly for a plant that
// is not standing (a plant the map has: the simulation draws no other).
void check_cells(const FieldSimulation &p_sim, const Model &p_model, int p_columns) {
	const std::vector<uint8_t> &hidden = p_sim.get_hidden_cells();
	for (uint32_t c = 0; c < p_model.cells.size(); ++c) {
		check(p_sim.get_cell_state(c) == p_model.cells[c]);
		const CellState &cell = p_model.cells[c];
		const bool map_type = cell.plant == p_model.map[c];
		if (!hidden.empty() && p_model.map[c] != 0) {
			const size_t byte = size_t(c / uint32_t(p_columns)) * p_sim.hidden_row_bytes() + (c % uint32_t(p_columns)) / 8;
			const bool bit = (hidden[byte] >> ((c % uint32_t(p_columns)) % 8)) & 1;
			check(bit == (cell.state != PlantState::STANDING || !map_type));
		}
		// A plant of another type than the map's is an added plant of that type, in that state.
		const uint32_t added = p_sim.plants().added_plant_at_cell(c);
		if (map_type || cell.plant == 0) {
			check(added == FieldPlants::NO_PLANT);
		} else {
			check(added != FieldPlants::NO_PLANT);
			check(p_sim.plants().cell_of_plant(added) == c);
			check(p_sim.plants().species_of(p_sim.plants().get_layout().plants[added]) == uint32_t(cell.plant - 1));
			check(p_sim.plants().get_plant_state(added) == cell.state);
		}
	}
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *p_data, size_t p_size) {
	Input in{ p_data, p_size };
	const int columns = 1 + in.next() % 24;
	const int rows = 1 + in.next() % 12;
	// The map: each cell nothing or one of three plant types, from the input.
	std::string text = std::to_string(columns) + " " + std::to_string(rows) + "\n";
	Model model;
	const char symbols[4] = { '.', '*', 'a', 'b' };
	for (int r = 0; r < rows; ++r) {
		for (int c = 0; c < columns; ++c) {
			const uint8_t kind = in.next() % 4;
			text += symbols[kind];
			model.map.push_back(kind); // '*' species 0 (plant byte 1), 'a' 1, 'b' 2
		}
		text += '\n';
	}
	FieldSimulation sim;
	MapError error;
	check(sim.load_map(text, U"", U"ab", "fuzz.field", MapLimits{}, error));
	check(sim.plants().get_map().plants == model.map);
	for (uint8_t plant : model.map) {
		model.cells.push_back(CellState{ plant, PlantState::STANDING, 0.0 });
	}
	const uint32_t cells = uint32_t(columns * rows);
	double now = 0.0;
	for (int step = 0; step < 200 && in.more(); ++step) {
		const uint8_t op = in.next();
		const uint32_t cell = in.next() % cells;
		std::vector<uint32_t> changed;
		std::vector<uint32_t> expected;
		switch (op % 10) {
			case 0:
			case 1:
			case 2: { // stand, flatten, cut: a cell and its neighbour (a list, repeats and all)
				const PlantState state = static_cast<PlantState>(op % 3);
				const std::vector<uint32_t> list = { cell, (cell + 1) % cells, cell };
				sim.change_cells(list, static_cast<FieldSimulation::CellAction>(op % 3), now, changed);
				for (uint32_t c : list) {
					if (model.set_state(c, state, now)) {
						expected.push_back(c);
					}
				}
				check(changed == expected);
				break;
			}
			case 3:
				sim.change_cells({ cell }, FieldSimulation::CellAction::REMOVE, now, changed);
				check(changed.size() == (model.remove(cell) ? 1u : 0u));
				break;
			case 4:
				sim.change_cells({ cell }, FieldSimulation::CellAction::RESTORE, now, changed);
				check(changed.size() == (model.restore(cell) ? 1u : 0u));
				break;
			case 5: { // time passes (in eighths of a second: exact in a save's milliseconds)
				now += double(in.next() % 64) * 0.125;
				std::vector<uint32_t> recovered;
				sim.advance_changes(now, recovered);
				model.advance(now, expected);
				std::sort(recovered.begin(), recovered.end());
				check(recovered == expected);
				break;
			}
			case 6: { // new regrowth timings (whole seconds; 0: never)
				std::array<Regrowth, FieldMap::MAX_SPECIES> timing{};
				for (uint32_t s = 0; s < 3; ++s) {
					timing[s] = Regrowth{ double(in.next() % 5), double(in.next() % 7) };
				}
				sim.set_regrowth(timing);
				model.regrowth = timing;
				break;
			}
			case 7: { // a pusher at the cell tramples what stands within half a cell of it
				const Pusher pusher{ { (float(cell % uint32_t(columns)) + 0.3f) * 0.5f, 0.5f, (float(cell / uint32_t(columns)) + 0.3f) * 0.5f },
					0.6f };
				sim.near().get_pushes().set_pushers(&pusher, 1);
				std::vector<FieldSimulation::Trampled> trampled;
				sim.trample(0.5f, now, trampled);
				for (const FieldSimulation::Trampled &each : trampled) {
					check(model.cells[each.cell].plant != 0 && model.cells[each.cell].state == PlantState::STANDING);
					model.set_state(each.cell, PlantState::FLATTENED, now);
				}
				break;
			}
			case 9: { // a plant of a type put in the cell and its neighbour, then a frame drawn
				const uint8_t species = in.next() % 3;
				const std::vector<uint32_t> list = { cell, (cell + 1) % cells };
				sim.put_cells(list, species, changed);
				for (uint32_t c : list) {
					if (model.put(c, species)) {
						expected.push_back(c);
					}
				}
				check(changed == expected);
				sim.update(0.016f);
				break;
			}
			case 8: { // the save, into a fresh simulation; one bit flipped and another map's, refused
				const std::vector<uint8_t> bytes = sim.save_changes(now);
				FieldSimulation other;
				check(other.load_map(text, U"", U"ab", "again.field", MapLimits{}, error));
				other.set_regrowth(model.regrowth);
				double clock = -1.0;
				check(other.load_changes(bytes, clock).empty());
				check(clock == now);
				check_cells(other, model, columns);
				std::vector<uint8_t> flipped = bytes;
				const size_t bit = in.next() * 131u + in.next();
				flipped[(bit / 8) % flipped.size()] ^= uint8_t(1u << (bit % 8));
				check(!sim.load_changes(flipped, clock).empty());
				std::string other_text = text;
				other_text[other_text.find('\n') + 1] = other_text[other_text.find('\n') + 1] == '*' ? '.' : '*';
				FieldSimulation stranger;
				check(stranger.load_map(other_text, U"", U"ab", "other.field", MapLimits{}, error));
				check(!stranger.load_changes(bytes, clock).empty());
				break;
			}
		}
		check_cells(sim, model, columns);
		check(sim.get_change_count() ==
				size_t(std::count_if(model.cells.begin(), model.cells.end(), [&](const CellState &p_cell) {
					const size_t c = size_t(&p_cell - model.cells.data());
					return !(p_cell == CellState{ model.map[c], PlantState::STANDING, 0.0 });
				})));
	}
	return 0;
}
