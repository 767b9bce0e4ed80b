# The Layout page: a read-only overview of track power, the locomotives and the feedback contacts.
target_sources(stellwerk-ui PRIVATE
    layout/ContactTableModel.cpp layout/ContactTableModel.h
    layout/LayoutOverview.cpp layout/LayoutOverview.h
)
