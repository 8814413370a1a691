# Finds the parts of OpenCV the planar mosaics use (core, imgproc, imgcodecs), as Debian packages
# them (libopencv-{core,imgproc,imgcodecs}-dev ship no CMake configuration of their own), and
# defines OpenCV::imaging.
find_path(OpenCVImaging_INCLUDE_DIR opencv2/core.hpp PATH_SUFFIXES opencv4)
find_library(OpenCVImaging_core_LIBRARY opencv_core)
find_library(OpenCVImaging_imgproc_LIBRARY opencv_imgproc)
find_library(OpenCVImaging_imgcodecs_LIBRARY opencv_imgcodecs)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(OpenCVImaging REQUIRED_VARS OpenCVImaging_INCLUDE_DIR
  OpenCVImaging_core_LIBRARY OpenCVImaging_imgproc_LIBRARY OpenCVImaging_imgcodecs_LIBRARY)
if(OpenCVImaging_FOUND AND NOT TARGET OpenCV::imaging)
  add_library(OpenCV::imaging INTERFACE IMPORTED)
  set_target_properties(OpenCV::imaging PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${OpenCVImaging_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${OpenCVImaging_imgcodecs_LIBRARY};${OpenCVImaging_imgproc_LIBRARY};${OpenCVImaging_core_LIBRARY}")
endif()
mark_as_advanced(OpenCVImaging_INCLUDE_DIR OpenCVImaging_core_LIBRARY OpenCVImaging_imgproc_LIBRARY
                 OpenCVImaging_imgcodecs_LIBRARY)
