// colcon-rsia model headers: the standard headers the real roscpp (and tf)
// headers include, which user code often relies on without including them.
//
// Most of the model mode's parse time is spent in these. model_mode.py
// therefore defines RSIA_MODEL_LEAN_STD and, for each costly header, a
// RSIA_MODEL_STD_<NAME> when the analysed sources name something it declares
// (std::cout, std::shared_ptr, sqrt, M_PI, ...); without RSIA_MODEL_LEAN_STD
// all of them are included.
#ifndef RSIA_MODEL_STD_H
#define RSIA_MODEL_STD_H

// (real library headers include <cassert> and <climits>: code uses
// assert and INT_MAX through them; both are small)
#include <cassert>
#include <climits>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#if !defined(RSIA_MODEL_LEAN_STD) || defined(RSIA_MODEL_STD_ALGORITHM)
#include <algorithm>
#endif
#if !defined(RSIA_MODEL_LEAN_STD) || defined(RSIA_MODEL_STD_CMATH)
#include <cmath>
#endif
#if !defined(RSIA_MODEL_LEAN_STD) || defined(RSIA_MODEL_STD_COMPLEX)
#include <complex>
#endif
#if !defined(RSIA_MODEL_LEAN_STD) || defined(RSIA_MODEL_STD_FUNCTIONAL)
#include <functional>
#endif
#if !defined(RSIA_MODEL_LEAN_STD) || defined(RSIA_MODEL_STD_IOMANIP)
#include <iomanip>
#endif
#if !defined(RSIA_MODEL_LEAN_STD) || defined(RSIA_MODEL_STD_IOSTREAM)
#include <iostream>
#endif
#if !defined(RSIA_MODEL_LEAN_STD) || defined(RSIA_MODEL_STD_LIST)
#include <list>
#endif
#if !defined(RSIA_MODEL_LEAN_STD) || defined(RSIA_MODEL_STD_MEMORY)
#include <memory>
#endif
#if !defined(RSIA_MODEL_LEAN_STD) || defined(RSIA_MODEL_STD_MUTEX)
#include <mutex>
#endif
#if !defined(RSIA_MODEL_LEAN_STD) || defined(RSIA_MODEL_STD_SET)
#include <set>
#endif
#if !defined(RSIA_MODEL_LEAN_STD) || defined(RSIA_MODEL_STD_SSTREAM)
#include <sstream>
#endif
#if !defined(RSIA_MODEL_LEAN_STD) || defined(RSIA_MODEL_STD_UNORDERED_MAP)
#include <unordered_map>
#endif

#endif  // RSIA_MODEL_STD_H
