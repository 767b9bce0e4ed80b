# The Locomotives page: the lokomotive.cs2 list and editor, saved into a CS2 configuration folder.
target_sources(stellwerk-ui PRIVATE
    locomotives/LocomotiveFileModel.cpp locomotives/LocomotiveFileModel.h
    locomotives/LocomotiveForm.cpp locomotives/LocomotiveForm.h
    locomotives/LocomotivePanel.cpp locomotives/LocomotivePanel.h
)
