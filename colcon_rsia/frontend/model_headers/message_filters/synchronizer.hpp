// colcon-rsia model of <message_filters/synchronizer.hpp> (ROS 2):
// Synchronizer<Policy> (derives from its policy), fed by 2..9 filters, with
// registerCallback. Jazzy/Rolling declare the inputs as a pack; Humble's
// fixed arities resolve the same way.
#ifndef RSIA_MODEL_MESSAGE_FILTERS_SYNCHRONIZER
#define RSIA_MODEL_MESSAGE_FILTERS_SYNCHRONIZER

#include <cstddef>
#include <string>
#include <tuple>

#include <message_filters/connection.hpp>
#include <message_filters/message_event.hpp>
#include <message_filters/null_types.hpp>
#include <message_filters/simple_filter.hpp>

namespace message_filters
{

template<class Policy>
class Synchronizer : public noncopyable, public Policy
{
public:
  using Messages = typename Policy::Messages;
  using Events = typename Policy::Events;

  template<class ... Fs>
  Synchronizer(Fs &... fs);
  template<class ... Fs>
  Synchronizer(const Policy & policy, Fs &... fs);
  Synchronizer(const Policy & policy);
  ~Synchronizer();

  void init();

  template<class ... Fs>
  void connectInput(Fs &... fs);

  template<class C>
  Connection registerCallback(C & callback);
  template<class C>
  Connection registerCallback(const C & callback);
  template<class C, typename T>
  Connection registerCallback(const C & callback, T * t);
  template<class C, typename T>
  Connection registerCallback(C & callback, T * t);

  void setName(const std::string & name);
  const std::string & getName();
  Policy * getPolicy();

  using Policy::add;
  template<int i>
  void add(const std::shared_ptr<typename std::tuple_element<i, Messages>::type const> & msg);
};

template<typename ... Ms>
struct PolicyBase
{
  static constexpr std::size_t N_MESSAGES = sizeof...(Ms);
  using Messages = std::tuple<Ms...>;
  using Events = std::tuple<MessageEvent<Ms const>...>;
};

}  // namespace message_filters

#endif  // RSIA_MODEL_MESSAGE_FILTERS_SYNCHRONIZER
