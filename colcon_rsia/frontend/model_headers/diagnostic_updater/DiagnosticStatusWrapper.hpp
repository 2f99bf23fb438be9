// colcon-rsia model of <diagnostic_updater/DiagnosticStatusWrapper.hpp>
// (the name of earlier ROS 2 releases)
#include <diagnostic_updater/diagnostic_status_wrapper.hpp>
