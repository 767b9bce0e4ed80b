# The bus monitor (every frame on the connection's buses, both ways: the bounded history, the filters,
# recording and timed replay of candump logs, the history setting) and the frame decoder tab.
target_sources(stellwerk-ui PRIVATE
    monitor/BusMonitorFilter.cpp monitor/BusMonitorFilter.h
    monitor/BusMonitorFilterBar.cpp monitor/BusMonitorFilterBar.h
    monitor/BusMonitorLog.cpp monitor/BusMonitorLog.h
    monitor/BusMonitorModel.cpp monitor/BusMonitorModel.h
    monitor/BusMonitorPanel.cpp monitor/BusMonitorPanel.h
    monitor/BusMonitorTable.cpp monitor/BusMonitorTable.h
    monitor/BusMonitorReplay.cpp monitor/BusMonitorReplay.h
    monitor/BusMonitorSettings.cpp monitor/BusMonitorSettings.h
    monitor/FrameDecoderPanel.cpp monitor/FrameDecoderPanel.h
    monitor/FrameDescriptions.cpp monitor/FrameDescriptions.h
)
