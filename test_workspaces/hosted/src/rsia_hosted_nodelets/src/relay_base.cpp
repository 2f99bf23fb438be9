#include <rsia_hosted_nodelets/relay_base.h>

namespace rsia_hosted_nodelets
{

void RelayBase::onInit()
{
  pnh_.reset(new ros::NodeHandle(getMTPrivateNodeHandle()));
}

}  // namespace rsia_hosted_nodelets
