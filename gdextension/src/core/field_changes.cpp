#include "field_changes.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace sunflower {

RowSet Regrowth::set(const ParameterSpec &p_spec, double p_value) {
	if (&p_spec == &param::PLANT_RECOVER_AFTER) {
		return set_row_value(flattened_seconds, p_spec, p_value);
	}
	return &p_spec == &param::PLANT_REGROW_AFTER ? set_row_value(cut_seconds, p_spec, p_value) : RowSet::OTHER;
}

namespace {

constexpr char MAGIC[4] = { 'S', 'F', 'C', 'H' };
constexpr size_t HEADER_BYTES = 4 + 2 + 2 + 4 + 4 + 8 + 8 + 4;
constexpr size_t CRC_BYTES = 4;

uint32_t crc32(const uint8_t *p_bytes, size_t p_count) {
	uint32_t crc = 0xFFFFFFFFu;
	for (size_t i = 0; i < p_count; i++) {
		crc ^= p_bytes[i];
		for (int bit = 0; bit < 8; bit++) {
			crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
		}
	}
	return ~crc;
}

void put_bytes(std::vector<uint8_t> &r_out, uint64_t p_value, int p_count) {
	for (int i = 0; i < p_count; i++) {
		r_out.push_back(static_cast<uint8_t>(p_value >> (8 * i)));
	}
}

void put_varint(std::vector<uint8_t> &r_out, uint64_t p_value) {
	while (p_value >= 0x80) {
		r_out.push_back(static_cast<uint8_t>(p_value | 0x80));
		p_value >>= 7;
	}
	r_out.push_back(static_cast<uint8_t>(p_value));
}

// Reads a save's bytes in order; any read past the end sets failed.
struct Reader {
	const std::vector<uint8_t> &bytes;
	size_t end = 0;
	size_t at = 0;
	bool failed = false;

	uint64_t fixed(int p_count) {
		if (at + static_cast<size_t>(p_count) > end) {
			failed = true;
			return 0;
		}
		uint64_t value = 0;
		for (int i = 0; i < p_count; i++) {
			value |= uint64_t(bytes[at++]) << (8 * i);
		}
		return value;
	}
	uint64_t varint() {
		uint64_t value = 0;
		for (int shift = 0; shift < 64; shift += 7) {
			if (at >= end) {
				failed = true;
				return 0;
			}
			const uint8_t byte = bytes[at++];
			value |= uint64_t(byte & 0x7F) << shift;
			if ((byte & 0x80) == 0) {
				return value;
			}
		}
		failed = true;
		return 0;
	}
};

double to_double(uint64_t p_bits) {
	double value = 0.0;
	std::memcpy(&value, &p_bits, sizeof(value));
	return value;
}

uint64_t to_bits(double p_value) {
	uint64_t bits = 0;
	std::memcpy(&bits, &p_value, sizeof(bits));
	return bits;
}

} // namespace

uint64_t map_fingerprint(const FieldMap &p_map) {
	uint64_t hash = 0xCBF29CE484222325ull;
	auto mix = [&hash](uint8_t p_byte) {
		hash ^= p_byte;
		hash *= 0x100000001B3ull;
	};
	for (int i = 0; i < 4; i++) {
		mix(static_cast<uint8_t>(static_cast<uint32_t>(p_map.columns) >> (8 * i)));
	}
	for (int i = 0; i < 4; i++) {
		mix(static_cast<uint8_t>(static_cast<uint32_t>(p_map.rows) >> (8 * i)));
	}
	for (uint8_t plant : p_map.plants) {
		mix(plant);
	}
	return hash;
}

void FieldChanges::reset(const FieldMap &p_map) {
	_columns = p_map.columns;
	_rows = p_map.rows;
	_species_count = p_map.species_count;
	_fingerprint = map_fingerprint(p_map);
	_map_plants = p_map.plants;
	_changes.clear();
	_due = {};
}

void FieldChanges::set_regrowth(const std::array<Regrowth, FieldMap::MAX_SPECIES> &p_regrowth) {
	_regrowth = p_regrowth;
	_due = {};
	for (const auto &[cell, state] : _changes) {
		_schedule(cell, state);
	}
}

CellState FieldChanges::get(uint32_t p_cell) const {
	const auto found = _changes.find(p_cell);
	if (found != _changes.end()) {
		return found->second;
	}
	CellState state;
	state.plant = p_cell < _map_plants.size() ? _map_plants[p_cell] : 0;
	return state;
}

void FieldChanges::_set(uint32_t p_cell, const CellState &p_state) {
	const bool as_map = p_state.plant == _map_plants[p_cell] && p_state.state == PlantState::STANDING;
	if (as_map) {
		_changes.erase(p_cell);
	} else {
		_changes[p_cell] = p_state;
		_schedule(p_cell, p_state);
	}
}

void FieldChanges::_schedule(uint32_t p_cell, const CellState &p_state) {
	if (p_state.plant == 0 || p_state.state == PlantState::STANDING) {
		return;
	}
	const Regrowth &regrowth = _regrowth[p_state.plant - 1];
	const double seconds = p_state.state == PlantState::FLATTENED ? regrowth.flattened_seconds : regrowth.cut_seconds;
	if (seconds > 0.0 && std::isfinite(seconds)) {
		_due.push(Due{ p_state.since + seconds, p_cell });
	}
}

bool FieldChanges::set_state(uint32_t p_cell, PlantState p_state, double p_now) {
	if (p_cell >= _map_plants.size() || !std::isfinite(p_now)) {
		return false;
	}
	CellState state = get(p_cell);
	// Nothing to change; and a cut plant has nothing standing to flatten.
	if (state.plant == 0 || state.state == p_state || (state.state == PlantState::CUT && p_state == PlantState::FLATTENED)) {
		return false;
	}
	state.state = p_state;
	state.since = p_state == PlantState::STANDING ? 0.0 : p_now;
	_set(p_cell, state);
	return true;
}

bool FieldChanges::remove(uint32_t p_cell) {
	if (p_cell >= _map_plants.size() || get(p_cell).plant == 0) {
		return false;
	}
	_set(p_cell, CellState{});
	return true;
}

bool FieldChanges::put(uint32_t p_cell, int p_species) {
	if (p_cell >= _map_plants.size() || p_species < 0 || p_species >= _species_count) {
		return false;
	}
	const CellState before = get(p_cell);
	CellState state;
	state.plant = static_cast<uint8_t>(p_species + 1);
	if (before == state) {
		return false;
	}
	_set(p_cell, state);
	return true;
}

bool FieldChanges::restore(uint32_t p_cell) {
	return _changes.erase(p_cell) != 0;
}

void FieldChanges::advance(double p_now, std::vector<uint32_t> &r_recovered) {
	while (!_due.empty() && _due.top().at <= p_now) {
		const Due due = _due.top();
		_due.pop();
		const auto found = _changes.find(due.cell);
		if (found == _changes.end() || found->second.state == PlantState::STANDING) {
			continue; // changed since it was scheduled
		}
		const Regrowth &regrowth = _regrowth[found->second.plant - 1];
		const double seconds = found->second.state == PlantState::FLATTENED ? regrowth.flattened_seconds : regrowth.cut_seconds;
		if (!(seconds > 0.0) || found->second.since + seconds != due.at) {
			continue; // scheduled for an earlier state (a plant trampled again, a cut one flattened)
		}
		CellState state = found->second;
		state.state = PlantState::STANDING;
		state.since = 0.0;
		_set(due.cell, state);
		r_recovered.push_back(due.cell);
	}
}

void cells_in_circle(int p_columns, int p_rows, float p_cell_size, const glm::vec2 &p_center, float p_radius,
		std::vector<uint32_t> &r_cells) {
	if (!(p_radius >= 0.0f) || !(p_cell_size > 0.0f) || !std::isfinite(p_center.x) || !std::isfinite(p_center.y) ||
			!std::isfinite(p_radius)) {
		return;
	}
	const glm::vec2 centre = p_center / p_cell_size;
	const float reach = p_radius / p_cell_size;
	const int column0 = std::max(0, static_cast<int>(std::floor(centre.x - reach)));
	const int column1 = std::min(p_columns - 1, static_cast<int>(std::floor(centre.x + reach)));
	const int row0 = std::max(0, static_cast<int>(std::floor(centre.y - reach)));
	const int row1 = std::min(p_rows - 1, static_cast<int>(std::floor(centre.y + reach)));
	for (int row = row0; row <= row1; row++) {
		for (int column = column0; column <= column1; column++) {
			const float dx = static_cast<float>(column) + 0.5f - centre.x;
			const float dz = static_cast<float>(row) + 0.5f - centre.y;
			if (dx * dx + dz * dz <= reach * reach) {
				r_cells.push_back(static_cast<uint32_t>(row) * static_cast<uint32_t>(p_columns) + static_cast<uint32_t>(column));
			}
		}
	}
}

void cells_in_rect(int p_columns, int p_rows, float p_cell_size, const glm::vec2 &p_min, const glm::vec2 &p_max,
		std::vector<uint32_t> &r_cells) {
	if (!(p_cell_size > 0.0f) || !std::isfinite(p_min.x) || !std::isfinite(p_min.y) || !std::isfinite(p_max.x) ||
			!std::isfinite(p_max.y)) {
		return;
	}
	// Cell c's centre (c + 0.5)·s lies in [min, max] for c from ceil(min/s − 0.5) to floor(max/s − 0.5).
	const int column0 = std::max(0, static_cast<int>(std::ceil(p_min.x / p_cell_size - 0.5f)));
	const int column1 = std::min(p_columns - 1, static_cast<int>(std::floor(p_max.x / p_cell_size - 0.5f)));
	const int row0 = std::max(0, static_cast<int>(std::ceil(p_min.y / p_cell_size - 0.5f)));
	const int row1 = std::min(p_rows - 1, static_cast<int>(std::floor(p_max.y / p_cell_size - 0.5f)));
	for (int row = row0; row <= row1; row++) {
		for (int column = column0; column <= column1; column++) {
			r_cells.push_back(static_cast<uint32_t>(row) * static_cast<uint32_t>(p_columns) + static_cast<uint32_t>(column));
		}
	}
}

std::vector<uint8_t> FieldChanges::save(double p_now) const {
	std::vector<uint8_t> out(MAGIC, MAGIC + 4);
	put_bytes(out, FIELD_CHANGES_VERSION, 2);
	put_bytes(out, 0, 2);
	put_bytes(out, static_cast<uint32_t>(_columns), 4);
	put_bytes(out, static_cast<uint32_t>(_rows), 4);
	put_bytes(out, _fingerprint, 8);
	put_bytes(out, to_bits(p_now), 8);
	put_bytes(out, static_cast<uint32_t>(_changes.size()), 4);
	int64_t previous = -1;
	for (const auto &[cell, state] : _changes) {
		put_varint(out, static_cast<uint64_t>(static_cast<int64_t>(cell) - previous - 1));
		previous = cell;
		out.push_back(static_cast<uint8_t>(state.plant | (static_cast<uint8_t>(state.state) << 4)));
		if (state.state != PlantState::STANDING) {
			const double age_ms = std::round((p_now - state.since) * 1000.0);
			put_varint(out, age_ms > 0.0 && std::isfinite(age_ms) ? static_cast<uint64_t>(std::min(age_ms, 9.0e15)) : 0);
		}
	}
	put_bytes(out, crc32(out.data(), out.size()), 4);
	return out;
}

std::string FieldChanges::load(const std::vector<uint8_t> &p_bytes, double &r_clock) {
	if (p_bytes.size() < HEADER_BYTES + CRC_BYTES || std::memcmp(p_bytes.data(), MAGIC, 4) != 0) {
		return "not a save of field changes (it does not begin with SFCH)";
	}
	Reader read{ p_bytes, p_bytes.size() - CRC_BYTES };
	read.at = 4;
	const uint64_t version = read.fixed(2);
	if (version > FIELD_CHANGES_VERSION || version == 0) {
		return "a save of version " + std::to_string(version) + ", which this version of the addon (" +
				std::to_string(FIELD_CHANGES_VERSION) + ") cannot read";
	}
	Reader crc{ p_bytes, p_bytes.size() };
	crc.at = p_bytes.size() - CRC_BYTES;
	if (crc.fixed(4) != crc32(p_bytes.data(), p_bytes.size() - CRC_BYTES)) {
		return "the save is corrupt (its checksum does not match its bytes)";
	}
	read.fixed(2); // flags
	const uint64_t columns = read.fixed(4);
	const uint64_t rows = read.fixed(4);
	const uint64_t fingerprint = read.fixed(8);
	const double clock = to_double(read.fixed(8));
	const uint64_t count = read.fixed(4);
	if (columns != static_cast<uint64_t>(_columns) || rows != static_cast<uint64_t>(_rows)) {
		return "the save was made on a map of " + std::to_string(columns) + " x " + std::to_string(rows) +
				" cells; this field's map has " + std::to_string(_columns) + " x " + std::to_string(_rows);
	}
	if (fingerprint != _fingerprint) {
		return "the save was made on another map of this size (its plants differ from this field's map)";
	}
	if (!std::isfinite(clock)) {
		return "the save's clock is not a number";
	}
	std::map<uint32_t, CellState> changes;
	const uint64_t cells = static_cast<uint64_t>(_columns) * static_cast<uint64_t>(_rows);
	uint64_t cell = 0;
	for (uint64_t i = 0; i < count; i++) {
		cell = (i == 0 ? 0 : cell + 1) + read.varint();
		const uint8_t packed = static_cast<uint8_t>(read.fixed(1));
		CellState state;
		state.plant = packed & 0x0F;
		const uint8_t kind = packed >> 4;
		if (read.failed || cell >= cells || state.plant > _species_count || kind > static_cast<uint8_t>(PlantState::CUT) ||
				(state.plant == 0 && kind != 0)) {
			return "the save is corrupt (change " + std::to_string(i + 1) + " of " + std::to_string(count) +
					" does not read as a cell of this map)";
		}
		state.state = static_cast<PlantState>(kind);
		if (state.state != PlantState::STANDING) {
			state.since = clock - static_cast<double>(read.varint()) / 1000.0;
		}
		if (state.plant == _map_plants[cell] && state.state == PlantState::STANDING) {
			return "the save is corrupt (change " + std::to_string(i + 1) + " changes nothing)";
		}
		changes[static_cast<uint32_t>(cell)] = state;
	}
	if (read.failed || read.at != read.end) {
		return "the save is corrupt (its length does not match its " + std::to_string(count) + " changes)";
	}
	_changes = std::move(changes);
	set_regrowth(_regrowth); // schedules the loaded states
	r_clock = clock;
	return "";
}

} // namespace sunflower
