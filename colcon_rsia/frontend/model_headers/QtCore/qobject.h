// colcon-rsia model of <QtCore/qobject.h>.
#include <rsia_model/qt_core.h>
