# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The call sites the source text shows: coverage's yardstick."""

from colcon_rsia.package.call_sites import cxx_call_sites


def test_a_call_that_passes_nothing_creates_no_endpoint():
    code = '\n'.join([
        'void TurnSignalDisplay::onEnable()',                     # 1
        '{',
        '  subscribe();',                                         # 3
        '  filter_sub_.subscribe ( );',                           # 4
        '  pub_ = nh_.advertise<std_msgs::String>();',            # 5
        '  sub_ = nh_.subscribe("in", 1, &D::cb, this);',         # 6
        '  out_ = nh_.advertise<std_msgs::String>("out", 1);',    # 7
        '  opts_sub_ = nh_.subscribe(',                           # 8
        '      options);',
        '  ready_ = helper_.advertise("");',                      # 10
        '}',
    ])
    # a display's or a filter's re-subscription (to the topic it has) and
    # a call without its topic make nothing; lines 6-10 pass theirs (an
    # empty literal is an argument)
    assert cxx_call_sites(code) == [
        (6, 'subscriber', 'subscribe'), (7, 'publisher', 'advertise'),
        (8, 'subscriber', 'subscribe'), (10, 'publisher', 'advertise')]


def test_a_call_qualified_by_a_template_parameter_is_no_ros_call():
    code = '\n'.join([
        'template <typename T, class Channel = Serial<int>>',     # 1
        'struct Poller',
        '{',
        '  static void start(double hz)',
        '  {',
        '    T::subscribe(hz);',                                  # 6
        '    Channel :: advertise(name_);',                       # 7
        '    sub_ = nh_.subscribe("in", 1, &T::cb, this);',       # 8
        '    pub_ = rclcpp::create_publisher<M>(node_, "o", 1);',  # 9
        '  }',
        '};',
    ])
    # `T::subscribe` calls a static member of the type a user gives the
    # template; ROS's `subscribe` and `advertise` are members called on a
    # handle, its free functions live in namespaces
    assert cxx_call_sites(code) == [
        (8, 'subscriber', 'subscribe'), (9, 'publisher', 'create_publisher')]
