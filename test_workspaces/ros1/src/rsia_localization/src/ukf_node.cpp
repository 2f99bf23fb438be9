// ukf_node: FilterNode<Ukf> (include/rsia_localization/filter_node.h)
#include "rsia_localization/filter_node.h"

int main(int argc, char** argv)
{
  ros::init(argc, argv, "ukf_se");
  ros::NodeHandle nh;
  ros::NodeHandle nh_priv("~");
  rsia_localization::FilterNode<rsia_localization::Ukf> filter(nh, nh_priv);
  filter.initialize();
  ros::spin();
  return 0;
}
