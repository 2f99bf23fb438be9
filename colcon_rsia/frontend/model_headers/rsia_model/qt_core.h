// colcon-rsia model of the parts of QtCore that pace ROS nodes driven by
// Qt's event loop: QObject (connect, startTimer/timerEvent), QTimer and the
// application classes, with the moc keywords as empty macros. Included by
// the <QObject>, <QTimer>, <QCoreApplication>, ... model headers.
#ifndef RSIA_MODEL_QT_CORE_H
#define RSIA_MODEL_QT_CORE_H

#include <chrono>
#include <string>

// (with the API rviz panels use to show what their nodes receive)
class QString
{
public:
  QString();
  QString(const char * text);
  static QString fromStdString(const std::string & text);
  static QString fromUtf8(const char * text, int size = -1);
  template<class Number>
  static QString number(Number value, char format = 'g', int precision = 6);
  template<class Number>
  static QString number(Number value, int base);
  std::string toStdString() const;
  template<class ... Values>
  QString arg(const Values & ...) const;
  QString left(int n) const;
  QString right(int n) const;
  QString rightRef(int n) const;
  QString mid(int position, int n = -1) const;
  bool isEmpty() const;
  int size() const;
  int length() const;
  double toDouble(bool * ok = nullptr) const;
  int toInt(bool * ok = nullptr, int base = 10) const;
  QString & operator+=(const QString & other);
  friend QString operator+(const QString & a, const QString & b);
  friend bool operator==(const QString & a, const QString & b);
  friend bool operator!=(const QString & a, const QString & b);
};

// the real macro also declares the meta-object functions (bodies moc
// writes); the two it defines in the class are kept, as the walk records
// the functions a package defines
#define Q_OBJECT \
public: \
  static inline QString tr(const char * s, const char * c = nullptr, int n = -1) \
  { \
    return QString(s); \
  } \
  static inline QString trUtf8(const char * s, const char * c = nullptr, int n = -1) \
  { \
    return QString(s); \
  } \
\
private:
#define Q_GADGET
#include <rsia_model/qt_keywords.h>
// the real macros also make strings of the signature: the analysis reads
// the slot's name from the source as written
#define SIGNAL(a) "2" #a
#define SLOT(a) "1" #a

class QEvent
{
public:
  virtual ~QEvent();
};

class QTimerEvent : public QEvent
{
public:
  explicit QTimerEvent(int timer_id);
  int timerId() const;
};

class QMetaObject
{
public:
  class Connection
  {
  public:
    Connection();
  };
};

class QObject
{
public:
  explicit QObject(QObject * parent = nullptr);
  virtual ~QObject();
  static QMetaObject::Connection connect(
    const QObject * sender, const char * signal, const QObject * receiver,
    const char * method, int type = 0);
  QMetaObject::Connection connect(
    const QObject * sender, const char * signal, const char * method,
    int type = 0) const;
  template <class Sender, class Signal, class Receiver, class Slot>
  static QMetaObject::Connection connect(
    const Sender * sender, Signal signal, const Receiver * receiver, Slot slot,
    int type = 0);
  template <class Sender, class Signal, class Functor>
  static QMetaObject::Connection connect(
    const Sender * sender, Signal signal, Functor functor);
  static bool disconnect(
    const QObject * sender, const char * signal, const QObject * receiver,
    const char * method);
  int startTimer(int interval, int timer_type = 0);
  int startTimer(std::chrono::milliseconds time, int timer_type = 0);
  void killTimer(int id);
  QObject * parent() const;
  void setParent(QObject * parent);
  void deleteLater();
  bool blockSignals(bool block);

protected:
  virtual bool event(QEvent * event);
  virtual void timerEvent(QTimerEvent * event);
};

class QTimer : public QObject
{
public:
  explicit QTimer(QObject * parent = nullptr);
  ~QTimer() override;
  bool isActive() const;
  int timerId() const;
  void setInterval(int msec);
  void setInterval(std::chrono::milliseconds value);
  int interval() const;
  int remainingTime() const;
  void setSingleShot(bool single_shot);
  bool isSingleShot() const;
  void start(int msec);
  void start(std::chrono::milliseconds msec);
  void start();
  void stop();
  template <class Functor>
  static void singleShot(int msec, Functor functor);
  template <class Receiver, class Functor>
  static void singleShot(int msec, const Receiver * receiver, Functor functor);
  static void singleShot(int msec, const QObject * receiver, const char * member);

  // the signal
  void timeout();
};

class QCoreApplication : public QObject
{
public:
  QCoreApplication(int & argc, char ** argv);
  ~QCoreApplication() override;
  static int exec();
  static void quit();
  static void exit(int code = 0);
  static void processEvents();
  static QCoreApplication * instance();
};

#endif  // RSIA_MODEL_QT_CORE_H
