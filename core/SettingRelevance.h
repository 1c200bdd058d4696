#pragma once

#include "Settings.h"

#include <QString>

namespace shadowlab {

// Why the current settings `s` leave the setting `key` unread, in a sentence that says what
// would make it count ("Contact shadows are off: turn on contact.enabled to use it"), or
// empty when it is read. The dock greys such a field and says this as its tooltip.
QString ignoredBecause(const Settings& s, const QString& key);

} // namespace shadowlab
