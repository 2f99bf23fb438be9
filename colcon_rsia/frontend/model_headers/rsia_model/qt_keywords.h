// colcon-rsia model of Qt's moc keywords, as empty macros: `private slots:`,
// `Q_SIGNALS:`, `emit changed();`. Included by qt_core.h and by the
// stand-in of every Qt header the model lacks (<QPushButton>,
// <QtWidgets/QWidget>), so that a widget's class declaration parses.
#ifndef RSIA_MODEL_QT_KEYWORDS_H
#define RSIA_MODEL_QT_KEYWORDS_H

#define Q_SLOTS
#define Q_SIGNALS public
#define Q_EMIT
#define slots
#define signals public
#define emit

#endif  // RSIA_MODEL_QT_KEYWORDS_H
