#include "core/field_map.h"

#include <doctest/doctest.h>

TEST_CASE("placeholder") {
	CHECK(1 == 1);
}
