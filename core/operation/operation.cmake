# The desktop's automatic operation (core/operation): the automation made for the railway and the layout in
# use, and the book of trains kept beside the layout, placed again after a restart.
stellwerk_core_library(operation)
target_sources(stellwerk-operation PRIVATE
    operation/Operation.cpp
    operation/Operation.h
    operation/TrainBook.cpp
    operation/TrainBook.h
    operation/TrainBookFile.cpp
    operation/TrainBookFile.h
)
target_link_libraries(stellwerk-operation PUBLIC stellwerk-automation stellwerk-model Qt6::Core)
