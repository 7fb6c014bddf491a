// SPDX-License-Identifier: GPL-3.0-or-later
// The library that carries the English plural forms (tolturn_en.qm) as a resource.
namespace tolturn {
void englishPluralForms() {}
} // namespace tolturn
