#pragma once
// Errors in the engine's ERR_FAIL_*_MSG style, naming the function, file and line. Two kinds:
// - SF_FAIL_*: the caller's mistake (a bad argument from a script): says what was wrong, returns.
// - SF_BUG_*: one of our own invariants broke: says so and asks for a report, returns.
#include "godot_api.h"

#include <string>

namespace gdx {
inline const char *const BUG_PREFIX = "this is a bug in the Sunflower Field extension, please report it: ";
}

#define SF_FAIL_COND_MSG(m_cond, m_msg)                                         \
	do {                                                                        \
		if (m_cond) {                                                           \
			::gdx::print_error(std::string(m_msg), __func__, __FILE__, __LINE__); \
			return;                                                             \
		}                                                                       \
	} while (false)

#define SF_FAIL_COND_V_MSG(m_cond, m_retval, m_msg)                             \
	do {                                                                        \
		if (m_cond) {                                                           \
			::gdx::print_error(std::string(m_msg), __func__, __FILE__, __LINE__); \
			return m_retval;                                                    \
		}                                                                       \
	} while (false)

#define SF_BUG_COND_MSG(m_cond, m_msg) SF_FAIL_COND_MSG(m_cond, std::string(::gdx::BUG_PREFIX) + (m_msg))
#define SF_BUG_COND_V_MSG(m_cond, m_retval, m_msg) SF_FAIL_COND_V_MSG(m_cond, m_retval, std::string(::gdx::BUG_PREFIX) + (m_msg))
