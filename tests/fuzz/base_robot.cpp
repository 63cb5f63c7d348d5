#include "base_robot.hpp"

#include "fuzz_support.hpp"

namespace rbdc_fuzz {
namespace {

const char* const kUrdf = R"(<?xml version="1.0"?>
<robot name="fuzz_base">
  <link name="trunk"><inertial><mass value="5"/>
    <inertia ixx="0.1" ixy="0" ixz="0" iyy="0.2" iyz="0" izz="0.25"/></inertial></link>
  <joint name="L_hip_joint" type="revolute"><parent link="trunk"/><child link="L_thigh"/>
    <origin xyz="0 0.1 0"/><axis xyz="0 1 0"/><limit lower="-1" upper="1" effort="10" velocity="10"/></joint>
  <link name="L_thigh"><inertial><origin xyz="0 0 -0.1"/><mass value="1"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.001"/></inertial></link>
  <joint name="L_slide" type="prismatic"><parent link="L_thigh"/><child link="L_shin"/>
    <origin xyz="0 0 -0.2"/><axis xyz="0 0 1"/><limit lower="-0.1" upper="0.1" effort="10" velocity="1"/></joint>
  <link name="L_shin"><inertial><mass value="0.5"/>
    <inertia ixx="0.005" ixy="0" ixz="0" iyy="0.005" iyz="0" izz="0.001"/></inertial></link>
  <joint name="L_foot_fixed" type="fixed"><parent link="L_shin"/><child link="L_foot"/>
    <origin xyz="0 0 -0.2"/></joint>
  <link name="L_foot"/>
  <joint name="R_hip_joint" type="revolute"><parent link="trunk"/><child link="R_thigh"/>
    <origin xyz="0 -0.1 0"/><axis xyz="0 1 0"/><limit lower="-1" upper="1" effort="10" velocity="10"/></joint>
  <link name="R_thigh"><inertial><origin xyz="0 0 -0.1"/><mass value="1"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.001"/></inertial></link>
  <joint name="R_slide" type="prismatic"><parent link="R_thigh"/><child link="R_shin"/>
    <origin xyz="0 0 -0.2"/><axis xyz="0 0 1"/><limit lower="-0.1" upper="0.1" effort="10" velocity="1"/></joint>
  <link name="R_shin"><inertial><mass value="0.5"/>
    <inertia ixx="0.005" ixy="0" ixz="0" iyy="0.005" iyz="0" izz="0.001"/></inertial></link>
  <joint name="R_foot_fixed" type="fixed"><parent link="R_shin"/><child link="R_foot"/>
    <origin xyz="0 0 -0.2"/></joint>
  <link name="R_foot"/>
  <joint name="arm_joint" type="continuous"><parent link="trunk"/><child link="arm"/>
    <origin xyz="0.2 0 0.1" rpy="0 1.5707963267948966 0"/><axis xyz="1 0 0"/></joint>
  <link name="arm"><inertial><origin xyz="0.1 0 0"/><mass value="0.3"/>
    <inertia ixx="0.001" ixy="0" ixz="0" iyy="0.002" iyz="0" izz="0.002"/></inertial></link>
</robot>
)";

}  // namespace

const std::string& base_robot_urdf() {
  static const InputFile file("-base.urdf");
  static const std::string& path = file.write(reinterpret_cast<const uint8_t*>(kUrdf), std::char_traits<char>::length(kUrdf));
  return path;
}

}  // namespace rbdc_fuzz
