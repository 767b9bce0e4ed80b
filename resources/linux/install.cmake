# Installing Stellwerk like a Linux desktop program (FHS paths under CMAKE_INSTALL_PREFIX), and the .deb
# that CPack makes from it (`cpack -G DEB` in the build folder; scripts/package.sh builds and checks it).
# The translations and the demo layout are compiled into the programs (Qt resources), so nothing at run
# time reads the build or source tree.
include(GNUInstallDirs)

set(STELLWERK_APP_ID io.github.stellwerk.Stellwerk)
set(linux_dir ${PROJECT_SOURCE_DIR}/resources/linux)

# The programs link Qt from the system and Stellwerk's own libraries statically: no run path is needed
# (qt_standard_project_setup() would add $ORIGIN/../lib, which Debian's policy does not want).
set_target_properties(stellwerk stellwerk-cli stellwerk-sim PROPERTIES INSTALL_RPATH "")
install(TARGETS stellwerk stellwerk-cli stellwerk-sim RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(FILES ${linux_dir}/${STELLWERK_APP_ID}.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES ${PROJECT_SOURCE_DIR}/resources/stellwerk.svg
        DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps
        RENAME ${STELLWERK_APP_ID}.svg)
configure_file(${linux_dir}/${STELLWERK_APP_ID}.metainfo.xml
               ${CMAKE_CURRENT_BINARY_DIR}/${STELLWERK_APP_ID}.metainfo.xml @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/${STELLWERK_APP_ID}.metainfo.xml
        DESTINATION ${CMAKE_INSTALL_DATADIR}/metainfo)
# The user guide where Help → User guide looks for it (share/doc/<package>, as Debian wants it).
set(stellwerk_docdir ${CMAKE_INSTALL_DATADIR}/doc/stellwerk)
install(FILES README.md DESTINATION ${stellwerk_docdir})
install(DIRECTORY docs/guide docs/screenshots DESTINATION ${stellwerk_docdir})

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME stellwerk)
set(CPACK_PACKAGE_VENDOR "Stellwerk")
set(CPACK_PACKAGE_CONTACT "Stellwerk developers <stellwerk@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_INSTALL_DIRECTORY stellwerk)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION misc)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON) # dependencies from the libraries the programs link (dpkg-shlibdeps)
# The icons of the function keys and the application are SVG: Qt's SVG image plugin draws them.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "qt6-svg-plugins | libqt6svg6")
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION "${PROJECT_DESCRIPTION}
 Drive trains, throw turnouts, watch occupancy and the CAN bus of a Märklin
 Central Station 2/3 or Gleisbox; runs on a built-in simulated station without
 hardware. Includes stellwerk-cli and the simulated station stellwerk-sim.")
include(CPack)
