// The third-party and standard headers nearly every translation unit of rollkin parses, precompiled once per
// build (ROLLKIN_PRECOMPILED_HEADERS, CMakeLists.txt) and included first in every file of the library, the
// output writers, the command line and the tests. Only headers that do not change with rollkin's code belong
// here, so that a change to a rollkin header recompiles no more than before (docs/benchmark.md, "Build times").
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <boost/math/constants/constants.hpp>
#include <nlohmann/json.hpp>
