// Fixture for the include check: a codec that reaches up into the model and into Qt (both forbidden).
#include "cs2/Header.h"
#include "model/Railway.h"

#include <QObject>
