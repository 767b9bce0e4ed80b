# Locomotive management and decoder programming: the Locomotives page (lokomotive.cs2 list and editor,
# saved into a CS2 configuration folder) and the Programming page (mfx search and registration, CVs).
target_sources(stellwerk-ui PRIVATE
    ${CMAKE_CURRENT_SOURCE_DIR}/LocomotiveFileModel.cpp ${CMAKE_CURRENT_SOURCE_DIR}/LocomotiveFileModel.h
    ${CMAKE_CURRENT_SOURCE_DIR}/LocomotiveForm.cpp ${CMAKE_CURRENT_SOURCE_DIR}/LocomotiveForm.h
    ${CMAKE_CURRENT_SOURCE_DIR}/LocomotivePanel.cpp ${CMAKE_CURRENT_SOURCE_DIR}/LocomotivePanel.h
    ${CMAKE_CURRENT_SOURCE_DIR}/ProgrammingPanel.cpp ${CMAKE_CURRENT_SOURCE_DIR}/ProgrammingPanel.h
)
