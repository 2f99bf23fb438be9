// colcon-rsia model of <message_filters/connection.h>.
#ifndef RSIA_MODEL_MESSAGE_FILTERS_CONNECTION_H
#define RSIA_MODEL_MESSAGE_FILTERS_CONNECTION_H

#include <boost/function.hpp>

namespace message_filters
{

class Connection
{
public:
  typedef boost::function<void(void)> VoidDisconnectFunction;
  typedef boost::function<void(const Connection&)> WithConnectionDisconnectFunction;

  Connection();
  Connection(const VoidDisconnectFunction& func);
  void disconnect();
};

}  // namespace message_filters

#endif  // RSIA_MODEL_MESSAGE_FILTERS_CONNECTION_H
