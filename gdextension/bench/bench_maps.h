#pragma once
// Maps the core benchmarks make in memory.
#include <string>

namespace sunflower_bench {

// A map of p_columns × p_rows cells, a sunflower in every one.
inline std::string rect_map(int p_columns, int p_rows) {
	std::string text = std::to_string(p_columns) + " " + std::to_string(p_rows) + "\n";
	const std::string row(static_cast<size_t>(p_columns), '*');
	for (int r = 0; r < p_rows; ++r) {
		text += row;
		text += '\n';
	}
	return text;
}

} // namespace sunflower_bench
