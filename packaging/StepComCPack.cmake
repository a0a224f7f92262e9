# The Debian package: `cmake --build build --target package` or `cd build && cpack -G DEB`.
# Included from the top CMakeLists.txt after every install() rule.
if(UNIX AND NOT APPLE)
    set(CPACK_GENERATOR DEB)
else()
    set(CPACK_GENERATOR ZIP) # Windows and macOS: see docs/building.md (windeployqt, macdeployqt)
endif()
set(CPACK_PACKAGE_NAME stepcom)
set(CPACK_PACKAGE_VENDOR "StepCom contributors")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "commissioning tool for a 2-axis Modbus RTU stepper controller")
string(CONCAT CPACK_PACKAGE_DESCRIPTION
    "StepCom finds a 2-axis stepper-motor controller on an RS-485/RS-232 line (Modbus RTU) or\n"
    "behind a Modbus TCP gateway, reads and sets each motor's parameters, limit and home\n"
    "inputs and homing order, jogs and homes the axes, runs arc and line interpolation, and\n"
    "saves the result to the controller's flash or to a profile file. Every write is checked\n"
    "against the register map first, then read back and compared.\n"
    "\n"
    "The package contains the window (stepcom), the command line tool for scripts and\n"
    "production lines (stepcomctl) and a simulated controller (stepcom-sim). English and\n"
    "Simplified Chinese.")
set(CPACK_PACKAGE_HOMEPAGE_URL ${PROJECT_HOMEPAGE_URL})
set(CPACK_PACKAGE_CONTACT "StepCom maintainers <stepcom@example.invalid>")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)

set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT) # stepcom_0.1.0_amd64.deb
set(CPACK_DEBIAN_PACKAGE_SECTION electronics)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER ${CPACK_PACKAGE_CONTACT})
# Depends come from the programs' shared libraries (dpkg-shlibdeps: libc6, libqt6core6,
# libqt6serialbus6, libqt6widgets6, libqt6svg6, the pendant's libqt6httpserver6,
# libqt6websockets6 and libqrencode4, the game pad's libsdl2-2.0-0, ...). Qt's own
# translations (QCommandLineParser's texts, standard buttons) are a separate package; the window on Wayland needs Qt's plugin.
# libqt6svg6 holds the plugins that draw the SVG window icon (iconengines/libqsvgicon.so):
# loaded at run time, so dpkg-shlibdeps cannot see it.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libqt6svg6")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "qt6-translations-l10n, qt6-wayland, fonts-noto-cjk")
set(CPACK_DEBIAN_COMPRESSION_TYPE xz)

include(CPack)
