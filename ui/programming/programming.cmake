# The Programming page: mfx search and registration, and a decoder's CVs read and written.
target_sources(stellwerk-ui PRIVATE
    programming/FoundDecoders.cpp programming/FoundDecoders.h
    programming/ProgrammingPanel.cpp programming/ProgrammingPanel.h
    programming/ProgrammingResultText.cpp programming/ProgrammingResultText.h
)
