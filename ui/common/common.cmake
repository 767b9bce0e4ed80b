# What several features share: the words and lamps for station state ("not reported", the status dots, the
# track power line, the "layout stopped" banner), the railway's locomotives as a table, the row index of
# such tables, two parts side by side or stacked as a panel's width allows, and where the remembered settings live.
target_sources(stellwerk-ui PRIVATE
    common/LayoutStateBanner.cpp common/LayoutStateBanner.h
    common/LocomotiveTableModel.cpp common/LocomotiveTableModel.h
    common/NotReported.cpp common/NotReported.h
    common/PowerStatus.cpp common/PowerStatus.h
    common/RowIndex.h
    common/SideBySide.cpp common/SideBySide.h
    common/StatusDot.cpp common/StatusDot.h
    common/StellwerkSettings.h
    common/WrappingGrid.cpp common/WrappingGrid.h
)
