#pragma once
// The headers nearly every test translation unit parses, precompiled once and reused by every
// test target (tests/CMakeLists.txt: about a third of a test unit's compile time is these).
// Only stable third-party and standard headers: a project header here would rebuild every test
// on each change.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
