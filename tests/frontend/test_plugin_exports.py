# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The plugins a source registers, read from its text."""

from colcon_rsia.frontend.cpp.plugin_exports import gazebo_exports

GAZEBO_SOURCE = """\
namespace sim_plugins
{
void Camera::Load() { if (ready_) { start(); } }

// what GZ_REGISTER_SENSOR_PLUGIN expands to, written out
extern "C" GZ_PLUGIN_VISIBLE gazebo::SensorPlugin * RegisterPlugin();
gazebo::SensorPlugin * RegisterPlugin()
{
  return (gazebo::CameraPlugin *)(new Camera());
}

namespace arm
{
GZ_REGISTER_MODEL_PLUGIN(Gripper)
}
}  // namespace sim_plugins
GZ_REGISTER_WORLD_PLUGIN(::Clock)
"""


def test_gazebo_plugins_by_macro_and_by_their_entry_point():
    # each class qualified by the namespaces it is named in; the entry
    # point's body is a scope of its own, which leaves those after it
    # as they are
    assert gazebo_exports(GAZEBO_SOURCE) == [
        ['sim_plugins::Camera', 'gazebo::SensorPlugin'],
        ['sim_plugins::arm::Gripper', 'gazebo::ModelPlugin'],
        ['Clock', 'gazebo::WorldPlugin'],
    ]
