// colcon-rsia model of <QtCore/qcoreapplication.h>.
#include <rsia_model/qt_core.h>
