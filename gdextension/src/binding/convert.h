#pragma once
// The one place where engine types and core (GLM / std) types meet.
#include "godot_api.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <string>

namespace gdx {

inline glm::vec2 to_core(const Vector2 &p_v) {
	return glm::vec2(p_v.x, p_v.y);
}
inline glm::vec3 to_core(const Vector3 &p_v) {
	return glm::vec3(p_v.x, p_v.y, p_v.z);
}
inline Vector3 to_godot(const glm::vec3 &p_v) {
	return Vector3{ p_v.x, p_v.y, p_v.z };
}
inline AABB to_godot_aabb(const glm::vec3 &p_min, const glm::vec3 &p_max) {
	return AABB{ to_godot(p_min), to_godot(p_max - p_min) };
}
inline std::string to_core(const PackedByteArray &p_bytes) {
	const uint8_t *data = p_bytes.data();
	return data ? std::string(reinterpret_cast<const char *>(data), static_cast<size_t>(p_bytes.size())) : std::string();
}
inline std::u32string to_core_u32(const String &p_text) {
	// Legend symbols: decoded from UTF-8 one code point at a time.
	const std::string utf8 = p_text.utf8();
	std::u32string out;
	for (size_t i = 0; i < utf8.size();) {
		const unsigned char lead = static_cast<unsigned char>(utf8[i]);
		const int extra = lead < 0x80 ? 0 : lead < 0xE0 ? 1 : lead < 0xF0 ? 2 : 3;
		char32_t code = extra == 0 ? lead : lead & (0x3F >> extra);
		for (int k = 1; k <= extra && i + size_t(k) < utf8.size(); ++k) {
			code = (code << 6) | (static_cast<unsigned char>(utf8[i + size_t(k)]) & 0x3F);
		}
		out.push_back(code);
		i += size_t(extra) + 1;
	}
	return out;
}

} // namespace gdx
