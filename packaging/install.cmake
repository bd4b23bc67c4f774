# `cmake --install build --prefix P` and CPack's .deb: the game and only what it reads at run time.
#   P/bin/arcfire                                 the program
#   P/lib/arcfire/libarcfire_image_codec.so       the image codec module (assets/image_codec.h)
#   P/share/arcfire/{assets,levels,shaders}       the data root (engine/core/data_root.h)
#   P/share/applications/arcfire.desktop          the desktop entry
#   P/share/icons/hicolor/256x256/apps/arcfire.png  the icon (made by arcfire-assetgen)
#   P/share/doc/arcfire/README.md
# The data root is found at <bin>/../share/arcfire, so the layout must keep bin/ and share/ siblings.
install(TARGETS arcfire RUNTIME DESTINATION bin)
install(TARGETS arcfire_image_codec LIBRARY DESTINATION lib/arcfire)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/assets ${PROJECT_SOURCE_DIR}/levels ${PROJECT_SOURCE_DIR}/shaders
        DESTINATION share/arcfire PATTERN "*.md" EXCLUDE)
install(FILES ${PROJECT_SOURCE_DIR}/packaging/arcfire.desktop DESTINATION share/applications)
install(FILES ${PROJECT_SOURCE_DIR}/packaging/arcfire.png DESTINATION share/icons/hicolor/256x256/apps)
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION share/doc/arcfire)

# The .deb (`cpack -G DEB` in the build folder, or `cmake --build build --target package`). Its
# Depends are computed by dpkg-shlibdeps from the libraries the program and the codec module
# link, plus the one library loaded by name; tests/cli/deb_package.sh checks them against ldd
# and dpkg -S.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME arcfire)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "Arcfire developers <arcfire@example.org>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "small 3-D space-combat game")
set(CPACK_PACKAGE_DESCRIPTION "Arcfire: a small 3-D space-combat game with particle effects, replays and an effect workbench.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_PACKAGE_SECTION games)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# libepoxy opens libEGL.so.1 at run time for headless rendering (no NEEDED entry, so
# dpkg-shlibdeps cannot see it); the window's GL comes with libglfw3's own dependencies.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libegl1")
set(CPACK_STRIP_FILES ON)
include(CPack)
