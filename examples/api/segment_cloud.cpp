// Segment a point cloud (.pcd, .ply, .xyz) into parts and write it back with a label per point.
// Normals are estimated when the file has none.
//   example_segment_cloud CLOUD OUT.pcd
#include <segmat/io/cloud.h>
#include <segmat/segmentation/cloud_segmentation.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <iostream>

int
main(int argc, char** argv)
{
  if (argc != 3) {
    std::cerr << "usage: example_segment_cloud CLOUD OUT.pcd\n";
    return 2;
  }
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  try {
    // Any PCL cloud will do; here only the points of the file are used.
    const segmat::io::LoadedCloud loaded = segmat::io::loadCloud(argv[1]);
    for (const pcl::PointNormal& p : *loaded.cloud)
      cloud->push_back(pcl::PointXYZ(p.x, p.y, p.z));
  } catch (const segmat::Error& e) {
    std::cerr << e.what() << '\n';
    return 2;
  }

  segmat::CloudSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud(cloud);
  seg.setNumberOfThreads(1); // labels do not depend on it
  std::vector<pcl::PointIndices> parts;
  if (!seg.segment(parts))
    return 1;
  std::cout << parts.size() << " parts of " << cloud->size() << " points\n";

  pcl::PointCloud<pcl::PointXYZL> labelled; // x y z and the part number
  seg.getLabeledCloud(labelled);
  segmat::io::saveLabeledCloudPcd(argv[2], labelled);
  return 0;
}
