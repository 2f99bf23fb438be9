// colcon-rsia model headers: the C++ standard headers, compiled once per
// language standard into a precompiled header that every model-mode parse
// loads first (model_mode/precompiled.py).
//
// Parsing these is most of a model-mode parse (about 0.5 s of 0.6 s), and
// they are the same for every unit. Those the model headers include are all
// here, with the ones ROS code most often relies on through the real
// headers. The C headers stay out but for those the model headers include:
// their global names (y0, index, ...) could clash with a package's own.
#ifndef RSIA_MODEL_PRECOMPILED_H
#define RSIA_MODEL_PRECOMPILED_H

#include <cstdarg>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <cmath>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <complex>
#include <condition_variable>
#include <deque>
#include <functional>
#include <future>
#include <initializer_list>
#include <iomanip>
#include <iosfwd>
#include <iostream>
#include <iterator>
#include <limits>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <numeric>
#include <optional>
#include <queue>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>
#include <tuple>
#include <type_traits>
#include <typeinfo>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#endif  // RSIA_MODEL_PRECOMPILED_H
