#pragma once
// SunflowerMap: a field map read and edited on its own, without a simulation: what the importer checks,
// the painter paints and the map tools resize and write (core field_map.h). The field's simulation
// reads its own copy (SunflowerSimulation::load_map).
#include "binding/godot_api.h"
#include "core/field_map.h"

class SunflowerMap {
public:
	static constexpr const char *CLASS = "SunflowerMap";
	static void bind_methods();

	// Reads a map (see fields/FORMAT.md): the error, or empty. On an error the map read before stays.
	gdx::String load(const gdx::PackedByteArray &p_text, const gdx::String &p_source, const gdx::String &p_legend,
			const gdx::String &p_plant_symbols, int64_t p_max_plants);
	// Parses a map as load does, keeping nothing: a check cheap enough for the main thread (a
	// million-cell map in milliseconds). The error, or empty. With p_any_symbol every printable symbol
	// is an object, whatever p_legend says (the importer's check).
	static gdx::String check(const gdx::PackedByteArray &p_text, const gdx::String &p_source, const gdx::String &p_legend,
			const gdx::String &p_plant_symbols, int64_t p_max_plants, bool p_any_symbol);
	// The columns, rows and plants ('*' and any legend plant cannot be told apart here: '*' only) of a
	// map that parses with any printable symbol as an object; empty when it does not parse.
	static gdx::PackedInt32Array get_figures(const gdx::PackedByteArray &p_text, int64_t p_max_plants);
	// A brush stroke (core paint_cells); p_weights over the cells of p_weights_rect (column, row,
	// columns, rows) when not empty: the brush follows a placement layer's filters. The changed cells,
	// as column, row pairs.
	gdx::PackedInt32Array paint(gdx::Vector2 p_center, double p_radius, const gdx::String &p_symbol, double p_density, int64_t p_seed,
			const gdx::PackedFloat32Array &p_weights, const gdx::PackedInt32Array &p_weights_rect);
	bool resize(int64_t p_columns, int64_t p_rows);
	gdx::PackedByteArray write() const;
	int64_t get_columns() const { return _map.columns; }
	int64_t get_rows() const { return _map.rows; }
	// Cells holding legend symbols, as triples (column, row, unicode code point).
	gdx::PackedInt32Array get_objects() const;

	// Shared with SunflowerSimulation: the limits for a field's max_plants (0: the parser's own).
	static sunflower::MapLimits limits_for(int64_t p_max_plants);
	static gdx::PackedInt32Array objects_of(const sunflower::FieldMap &p_map);

private:
	sunflower::FieldMap _map;
	std::u32string _plant_symbols;
};
