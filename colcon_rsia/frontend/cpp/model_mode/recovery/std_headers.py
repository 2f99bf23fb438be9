# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The standard header that declares a name of std:: (data).

A fact of the C++ standard library, not of any one workspace: the rule
that completes an unknown ``std::`` name includes the header this table
gives.
"""

# what a name of std:: needs (the model includes the costly ones only when
# the sources name them; a name reached otherwise is repaired here)
STD_HEADER_OF = {
    name: header for header, names in {
        'algorithm': 'sort stable_sort find find_if count count_if copy '
                     'copy_if fill transform remove remove_if replace '
                     'reverse rotate unique min max minmax min_element '
                     'max_element clamp all_of any_of none_of for_each '
                     'lower_bound upper_bound binary_search equal search '
                     'partition nth_element',
        'cmath': 'sqrt cbrt hypot pow exp log log10 log2 sin cos tan asin '
                 'acos atan atan2 sinh cosh tanh fabs abs floor ceil round '
                 'lround trunc fmod remainder copysign isnan isinf isfinite '
                 'fmin fmax signbit',
        'numeric': 'accumulate iota inner_product partial_sum reduce gcd lcm '
                   'adjacent_difference transform_reduce',
        'memory': 'shared_ptr unique_ptr weak_ptr make_shared make_unique '
                  'enable_shared_from_this static_pointer_cast '
                  'dynamic_pointer_cast',
        'functional': 'function bind placeholders ref cref hash invoke '
                      'mem_fn reference_wrapper',
        'sstream': 'stringstream ostringstream istringstream '
                   'basic_stringstream basic_ostringstream '
                   'basic_istringstream',
        'iostream': 'cout cerr clog cin',
        'iomanip': 'setprecision setw setfill put_time quoted',
        'limits': 'numeric_limits',
        'mutex': 'mutex recursive_mutex timed_mutex lock_guard unique_lock '
                 'scoped_lock call_once once_flag',
        'shared_mutex': 'shared_mutex shared_lock',
        'condition_variable': 'condition_variable',
        'thread': 'thread this_thread',
        'atomic': 'atomic atomic_bool atomic_int',
        'chrono': 'chrono',
        'optional': 'optional nullopt make_optional',
        'variant': 'variant visit holds_alternative monostate',
        'tuple': 'tuple make_tuple tie get',
        'utility': 'pair make_pair move forward swap exchange',
        'map': 'map multimap',
        'unordered_map': 'unordered_map',
        'set': 'set multiset',
        'unordered_set': 'unordered_set',
        'list': 'list',
        'deque': 'deque',
        'queue': 'queue priority_queue',
        'stack': 'stack',
        'array': 'array',
        'string_view': 'string_view',
        'regex': 'regex regex_match regex_search regex_replace smatch',
        'random': 'mt19937 random_device uniform_real_distribution '
                  'uniform_int_distribution normal_distribution',
        'future': 'future promise async',
        'filesystem': 'filesystem',
        'fstream': 'ifstream ofstream fstream basic_ifstream '
                   'basic_ofstream basic_fstream',
        'iterator': 'back_inserter inserter distance advance next prev '
                    'begin end',
        'stdexcept': 'runtime_error logic_error invalid_argument '
                     'out_of_range',
        'cstring': 'memcpy memset strlen strcmp strncpy',
        'cstdlib': 'exit getenv abort',
        'complex': 'complex',
        'bitset': 'bitset',
        'numbers': 'numbers',
    }.items() for name in names.split()}
