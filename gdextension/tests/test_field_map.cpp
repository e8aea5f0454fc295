#include "field_map.h"

#include <doctest/doctest.h>

using namespace sunflower;

namespace {

struct Parsed {
	bool ok = false;
	FieldMap map;
	MapError error;
};

Parsed parse(const std::string &p_text, const std::u32string &p_legend = U"", MapLimits p_limits = {}) {
	Parsed out;
	out.ok = parse_field_map(p_text, p_legend, "test.field", p_limits, out.map, out.error);
	return out;
}

void check_error(const std::string &p_text, int p_line, int p_column, const std::string &p_fragment) {
	CAPTURE(p_text);
	const Parsed result = parse(p_text);
	REQUIRE_FALSE(result.ok);
	CAPTURE(result.error.to_string());
	CHECK(result.error.line == p_line);
	CHECK(result.error.column == p_column);
	CHECK(result.error.message.find(p_fragment) != std::string::npos);
	CHECK(result.error.to_string().rfind("test.field:", 0) == 0);
}

} // namespace

TEST_CASE("a thesis-style map: header COLUMNS ROWS, '*' plants, spaces empty") {
	const Parsed result = parse("4 3\n* *\n.**.\n   *\n");
	REQUIRE(result.ok);
	CHECK(result.map.columns == 4);
	CHECK(result.map.rows == 3);
	CHECK(result.map.plant_count == 5);
	CHECK(result.map.has_plant(0, 0));
	CHECK_FALSE(result.map.has_plant(1, 0));
	CHECK(result.map.has_plant(2, 0));
	CHECK_FALSE(result.map.has_plant(3, 0)); // short row padded
	CHECK(result.map.has_plant(1, 1));
	CHECK(result.map.has_plant(3, 2));
}

TEST_CASE("accepted oddities: BOM, CRLF, comments before the header, trailing blank lines, missing rows") {
	const Parsed result = parse("\xEF\xBB\xBF# a comment\r\n\r\n  # another\r\n3 4\r\n***\r\n*\r\n\r\n\r\n");
	REQUIRE(result.ok);
	CHECK(result.map.columns == 3);
	CHECK(result.map.rows == 4);
	CHECK(result.map.plant_count == 4);
	const Parsed no_newline = parse("2 1\n**");
	REQUIRE(no_newline.ok);
	CHECK(no_newline.map.plant_count == 2);
	const Parsed trailing_spaces = parse("2 1\n**    \n");
	REQUIRE(trailing_spaces.ok);
}

TEST_CASE("legend symbols become objects; unknown symbols are errors") {
	const Parsed result = parse("3 1\n*S*\n", U"S");
	REQUIRE(result.ok);
	REQUIRE(result.map.objects.size() == 1);
	CHECK(result.map.objects[0].column == 1);
	CHECK(result.map.objects[0].symbol == U'S');
	check_error("3 1\n*S*\n", 2, 2, "unexpected 'S'");
	const Parsed unicode = parse("2 1\n*\xC3\xA9\n", U"\u00E9");
	REQUIRE(unicode.ok);
	CHECK(unicode.map.objects[0].symbol == U'\u00E9');
}

TEST_CASE("the importer's reading keeps every printable symbol, and no control character") {
	MapLimits any;
	any.any_object_symbol = true;
	const Parsed result = parse("5 1\n*S?\xC3\xA9~\n", U"", any);
	REQUIRE(result.ok);
	REQUIRE(result.map.objects.size() == 4);
	CHECK(result.map.objects[0].symbol == U'S');
	CHECK(result.map.objects[1].symbol == U'?');
	CHECK(result.map.objects[2].symbol == U'\u00E9');
	CHECK(result.map.objects[3].symbol == U'~');
	CHECK(result.map.plant_count == 1);
	for (const std::string &bad : { std::string("3 1\n*\t*\n"), std::string("3 1\n*\x01*\n"), std::string("3 1\n*\x7F*\n"),
				 std::string("3 1\n*\xC2\x85*\n"), std::string("3 1\n*\xFF*\n") }) {
		CAPTURE(bad);
		const Parsed refused = parse(bad, U"", any);
		CHECK_FALSE(refused.ok);
		CHECK(refused.error.line == 2);
		CHECK(refused.error.column == 2);
	}
	// Without it, a printable symbol the legend lacks is named as one the legend could map.
	const Parsed strict = parse("3 1\n*S*\n");
	REQUIRE_FALSE(strict.ok);
	CHECK(strict.error.message.find("a symbol the field's legend maps") != std::string::npos);
}

TEST_CASE("header errors name line and column") {
	check_error("", 0, 0, "empty");
	check_error("# only a comment\n\n", 2, 0, "no header");
	check_error("abc 3\n", 1, 1, "expected a whole number for COLUMNS");
	check_error("4\n", 1, 2, "before ROWS");
	check_error("4 x\n", 1, 3, "expected a whole number for ROWS");
	check_error("0 3\n", 1, 1, "positive");
	check_error("4 -3\n", 1, 3, "positive");
	check_error("4 3 5\n", 1, 5, "after the header");
	check_error("4,3\n", 1, 2, "','");
	check_error("99999999999 2\n", 1, 1, "larger than the limit");
}

TEST_CASE("row errors name line and character column") {
	check_error("3 2\n***\n****\n", 3, 4, "longer than the 3 columns");
	check_error("3 1\n***\n*\n", 3, 1, "more rows");
	check_error("3 1\n*\t*\n", 2, 2, "tab");
	check_error(std::string("3 1\n*\0*\n", 8), 2, 2, "NUL");
	const Parsed wide = parse("3 1\n\xC3\xA9*x\n", U"\u00E9"); // the column counts characters, not bytes
	REQUIRE_FALSE(wide.ok);
	CHECK(wide.error.column == 3);
	check_error("3 1\n\xC3\xA9\n", 2, 1, "U+00E9");
	check_error("3 1\n*\xFF*\n", 2, 2, "not valid UTF-8");
	check_error("3 1\n*\x01*\n", 2, 2, "U+0001");
}

TEST_CASE("limits guard against huge maps before allocating") {
	MapLimits limits;
	limits.max_cells = 1000;
	const Parsed big = parse("100000 100000\n*\n", U"", limits);
	REQUIRE_FALSE(big.ok);
	CHECK(big.error.message.find("cells") != std::string::npos);
	limits = MapLimits{};
	limits.max_plants = 3;
	const Parsed many = parse("5 1\n*****\n", U"", limits);
	REQUIRE_FALSE(many.ok);
	CHECK(many.error.column == 4);
	CHECK(many.error.message.find("maximum") != std::string::npos);
}
