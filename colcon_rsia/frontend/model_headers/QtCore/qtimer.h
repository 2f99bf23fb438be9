// colcon-rsia model of <QtCore/qtimer.h>.
#include <rsia_model/qt_core.h>
