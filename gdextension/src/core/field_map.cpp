#include "field_map.h"

#include <charconv>
#include <cstdio>

namespace sunflower {

std::string MapError::to_string() const {
	std::string out = source.empty() ? std::string("<map>") : source;
	if (line > 0) {
		out += ":" + std::to_string(line);
		if (column > 0) {
			out += ":" + std::to_string(column);
		}
	}
	return out + ": " + message;
}

namespace {

// Decodes one UTF-8 character at p_text[r_pos]; malformed bytes decode as U+FFFD, one byte each.
char32_t decode_utf8(std::string_view p_text, size_t &r_pos) {
	const auto byte = [&](size_t p_i) { return static_cast<unsigned char>(p_text[p_i]); };
	const unsigned char lead = byte(r_pos);
	int extra = 0;
	char32_t code = 0;
	if (lead < 0x80) {
		r_pos += 1;
		return lead;
	} else if ((lead & 0xE0) == 0xC0) {
		extra = 1;
		code = lead & 0x1F;
	} else if ((lead & 0xF0) == 0xE0) {
		extra = 2;
		code = lead & 0x0F;
	} else if ((lead & 0xF8) == 0xF0) {
		extra = 3;
		code = lead & 0x07;
	} else {
		r_pos += 1;
		return 0xFFFD;
	}
	if (r_pos + static_cast<size_t>(extra) >= p_text.size()) { // truncated sequence
		r_pos += 1;
		return 0xFFFD;
	}
	for (int i = 1; i <= extra; ++i) {
		const unsigned char next = byte(r_pos + static_cast<size_t>(i));
		if ((next & 0xC0) != 0x80) {
			r_pos += 1;
			return 0xFFFD;
		}
		code = (code << 6) | (next & 0x3F);
	}
	r_pos += static_cast<size_t>(extra) + 1;
	return code;
}

std::string describe_char(char32_t p_char) {
	char buffer[48];
	if (p_char == '\t') {
		return "tab character (use spaces)";
	} else if (p_char == 0) {
		return "NUL byte";
	} else if (p_char == 0xFFFD) {
		return "bytes that are not valid UTF-8";
	} else if (p_char < 0x20 || p_char == 0x7F) {
		std::snprintf(buffer, sizeof(buffer), "control character U+%04X", static_cast<unsigned>(p_char));
	} else if (p_char < 0x80) {
		std::snprintf(buffer, sizeof(buffer), "'%c'", static_cast<char>(p_char));
	} else {
		std::snprintf(buffer, sizeof(buffer), "character U+%04X", static_cast<unsigned>(p_char));
	}
	return buffer;
}

struct Line {
	std::string_view text;
	int number = 0;
};

class LineReader {
public:
	explicit LineReader(std::string_view p_text) :
			_text(p_text) {
		if (_text.size() >= 3 && _text.substr(0, 3) == "\xEF\xBB\xBF") {
			_text.remove_prefix(3); // UTF-8 byte order mark
		}
	}

	bool next(Line &r_line) {
		if (_pos >= _text.size()) {
			return false;
		}
		size_t end = _text.find('\n', _pos);
		if (end == std::string_view::npos) {
			end = _text.size();
		}
		std::string_view line = _text.substr(_pos, end - _pos);
		if (!line.empty() && line.back() == '\r') {
			line.remove_suffix(1); // CRLF
		}
		_pos = end + 1;
		r_line.text = line;
		r_line.number = ++_number;
		return true;
	}

private:
	std::string_view _text;
	size_t _pos = 0;
	int _number = 0;
};

bool is_blank(char p_c) {
	return p_c == ' ' || p_c == '\t';
}

// Reads a positive decimal at p_line[r_pos]; on failure fills r_error.
bool read_size(const Line &p_line, size_t &r_pos, const char *p_what, int p_max, int &r_value, MapError &r_error) {
	const std::string_view text = p_line.text;
	while (r_pos < text.size() && is_blank(text[r_pos])) {
		++r_pos;
	}
	r_error.line = p_line.number;
	r_error.column = static_cast<int>(r_pos) + 1;
	if (r_pos >= text.size()) {
		r_error.message = std::string("the header ends before ") + p_what + "; expected \"COLUMNS ROWS\", e.g. \"40 30\"";
		return false;
	}
	const size_t start = r_pos;
	if (text[r_pos] == '-' || text[r_pos] == '+') {
		++r_pos;
	}
	while (r_pos < text.size() && text[r_pos] >= '0' && text[r_pos] <= '9') {
		++r_pos;
	}
	const std::string_view digits = text.substr(start, r_pos - start);
	if (r_pos < text.size() && !is_blank(text[r_pos])) {
		size_t bad = r_pos;
		r_error.column = static_cast<int>(bad) + 1;
		r_error.message = std::string("expected a whole number for ") + p_what + " but found " +
				describe_char(decode_utf8(text, bad));
		return false;
	}
	if (digits.empty() || digits == "-" || digits == "+") {
		r_error.message = std::string("expected a whole number for ") + p_what;
		return false;
	}
	if (digits[0] == '-') {
		r_error.message = std::string(p_what) + " must be positive, not " + std::string(digits);
		return false;
	}
	std::string_view unsigned_digits = digits[0] == '+' ? digits.substr(1) : digits;
	int64_t value = 0;
	for (char c : unsigned_digits) {
		value = value * 10 + (c - '0');
		if (value > p_max) {
			r_error.message = std::string(p_what) + " " + std::string(digits) + " is larger than the limit of " +
					std::to_string(p_max);
			return false;
		}
	}
	if (value == 0) {
		r_error.message = std::string(p_what) + " must be positive, not 0";
		return false;
	}
	r_value = static_cast<int>(value);
	return true;
}

} // namespace

std::u32string decode_utf8_text(std::string_view p_text) {
	std::u32string out;
	for (size_t pos = 0; pos < p_text.size();) {
		out.push_back(decode_utf8(p_text, pos));
	}
	return out;
}

bool is_printable_symbol(char32_t p_symbol) {
	return p_symbol >= 0x20 && p_symbol != 0x7F && !(p_symbol >= 0x80 && p_symbol < 0xA0) && p_symbol != 0xFFFD &&
			p_symbol <= 0x10FFFF;
}

bool parse_field_map(std::string_view p_text, std::u32string_view p_legend, const std::string &p_source,
		const MapLimits &p_limits, FieldMap &r_map, MapError &r_error) {
	return parse_field_map(p_text, p_legend, std::u32string_view(), p_source, p_limits, r_map, r_error);
}

bool parse_field_map(std::string_view p_text, std::u32string_view p_legend, std::u32string_view p_plant_symbols,
		const std::string &p_source, const MapLimits &p_limits, FieldMap &r_map, MapError &r_error) {
	r_error = MapError{ p_source, 0, 0, {} };
	r_map = FieldMap{};
	if (p_plant_symbols.size() >= size_t(FieldMap::MAX_SPECIES)) {
		r_error.message = "the legend names " + std::to_string(p_plant_symbols.size()) + " plant types besides '*'; at most " +
				std::to_string(FieldMap::MAX_SPECIES - 1) + " are allowed";
		return false;
	}
	r_map.species_count = 1 + int(p_plant_symbols.size());
	LineReader reader(p_text);
	Line line;

	// Header: the first line that is neither blank nor a '#' comment.
	bool have_header = false;
	while (reader.next(line)) {
		size_t first = 0;
		while (first < line.text.size() && is_blank(line.text[first])) {
			++first;
		}
		if (first == line.text.size() || line.text[first] == '#') {
			std::string_view kept = line.text;
			while (!kept.empty() && kept.back() == '\r') {
				kept.remove_suffix(1); // written back with LF ends only
			}
			r_map.preamble.emplace_back(kept);
			continue;
		}
		have_header = true;
		break;
	}
	if (!have_header) {
		r_error.line = p_text.empty() ? 0 : line.number;
		r_error.message = p_text.empty() ? "the file is empty; expected a header \"COLUMNS ROWS\""
										 : "no header found; expected a line \"COLUMNS ROWS\", e.g. \"40 30\"";
		return false;
	}
	size_t pos = 0;
	int columns = 0;
	int rows = 0;
	if (!read_size(line, pos, "COLUMNS", p_limits.max_side, columns, r_error) ||
			!read_size(line, pos, "ROWS", p_limits.max_side, rows, r_error)) {
		return false;
	}
	while (pos < line.text.size() && is_blank(line.text[pos])) {
		++pos;
	}
	if (pos < line.text.size()) {
		size_t bad = pos;
		r_error.line = line.number;
		r_error.column = static_cast<int>(pos) + 1;
		r_error.message = "unexpected " + describe_char(decode_utf8(line.text, bad)) +
				" after the header; expected just \"COLUMNS ROWS\"";
		return false;
	}
	const int header_line = line.number;
	const int64_t cells = int64_t(columns) * int64_t(rows);
	if (cells > p_limits.max_cells) {
		r_error.line = header_line;
		r_error.column = 1;
		r_error.message = "a " + std::to_string(columns) + " x " + std::to_string(rows) + " map has " +
				std::to_string(cells) + " cells, more than the limit of " + std::to_string(p_limits.max_cells);
		return false;
	}

	r_map.columns = columns;
	r_map.rows = rows;
	r_map.plants.assign(static_cast<size_t>(cells), 0);
	int64_t dots = 0; // how the file writes empty cells inside rows, to write them back alike
	int64_t spaces = 0;
	int row = 0;
	while (reader.next(line)) {
		if (row >= rows) {
			// Only blank lines may follow the declared rows.
			for (size_t i = 0; i < line.text.size(); ++i) {
				if (line.text[i] != ' ') {
					r_error.line = line.number;
					r_error.column = 1;
					r_error.message = "more rows than the " + std::to_string(rows) + " the header (line " +
							std::to_string(header_line) + ") declares";
					return false;
				}
			}
			continue;
		}
		size_t byte = 0;
		int column = 0;
		while (byte < line.text.size()) {
			const char32_t symbol = decode_utf8(line.text, byte);
			if (column >= columns) {
				if (symbol == ' ') {
					++column;
					continue; // trailing spaces past the declared width are harmless
				}
				r_error.line = line.number;
				r_error.column = column + 1;
				r_error.message = "row " + std::to_string(row + 1) + " is longer than the " + std::to_string(columns) +
						" columns the header declares (found " + describe_char(symbol) + ")";
				return false;
			}
			const size_t species = symbol == '*' ? 0
					: symbol != 0 && symbol != 0xFFFD && p_plant_symbols.find(symbol) != std::u32string_view::npos
					? 1 + p_plant_symbols.find(symbol)
					: size_t(FieldMap::MAX_SPECIES);
			if (species < size_t(FieldMap::MAX_SPECIES)) {
				r_map.plants[static_cast<size_t>(row) * static_cast<size_t>(columns) + static_cast<size_t>(column)] =
						static_cast<uint8_t>(1 + species);
				if (++r_map.plant_count > p_limits.max_plants) {
					r_error.line = line.number;
					r_error.column = column + 1;
					r_error.message = "the map has more than " + std::to_string(p_limits.max_plants) +
							" sunflowers, the configured maximum";
					return false;
				}
			} else if (symbol == ' ' || symbol == '.') {
				dots += symbol == '.' ? 1 : 0;
				spaces += symbol == ' ' ? 1 : 0;
			} else if (is_printable_symbol(symbol) &&
					(p_limits.any_object_symbol || p_legend.find(symbol) != std::u32string_view::npos)) {
				r_map.objects.push_back(MapObject{ column, row, symbol });
			} else {
				r_error.line = line.number;
				r_error.column = column + 1;
				r_error.message = "unexpected " + describe_char(symbol) + "; expected '*' (a sunflower), ' ' or '.' (nothing)" +
						(is_printable_symbol(symbol) ? std::string(", or a symbol the field's legend maps") : std::string());
				return false;
			}
			++column;
		}
		++row;
	}
	r_map.empty_symbol = dots > spaces ? '.' : ' ';
	return true;
}

} // namespace sunflower
