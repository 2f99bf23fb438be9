// ekf_node: FilterNode<Ekf> (include/rsia_localization/filter_node.h)
#include "rsia_localization/filter_node.h"

int main(int argc, char** argv)
{
  ros::init(argc, argv, "ekf_se");
  ros::NodeHandle nh;
  ros::NodeHandle nh_priv("~");
  rsia_localization::FilterNode<rsia_localization::Ekf> filter(nh, nh_priv);
  filter.initialize();
  ros::spin();
  return 0;
}
