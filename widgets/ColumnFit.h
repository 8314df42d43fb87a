#pragma once
// Column widths that fit their content (no "Link / a", no "2026-11-23 …"): each column is
// made at least as wide as its header text and the cells of the rows in view (the view's own size hints,
// so delegates and fonts count). Cheap enough for a timer: only the visible rows are measured.
class QHeaderView;
class QTableView;

namespace ocu {

// Widens (never narrows) every column of the view except stretched ones.
// Returns how many columns were widened.
int fitColumnsToContent(QTableView* view);

// Width the header section needs to show its title unelided (with the sort indicator's room).
int headerTextWidth(const QHeaderView* header, int section);

// Calls fitColumnsToContent when rows arrive or the view is shown, at most once a second.
void keepColumnsFitted(QTableView* view);

// A fitted column never grows past maxPx (but always shows its header title): a long machine id must not
// squeeze the stretched column of a narrow laptop screen; the model's tooltip shows the full text.
void setColumnFitCap(QTableView* view, int column, int maxPx);

// Sets every fitted (not stretched) column to its header title's width, so that fitting starts from the
// title rather than the header's default section size (100 px for a two-digit count column).
void startColumnsAtHeaderWidth(QTableView* view);

// Gives the view a horizontal header whose titles are elided where their column is narrower than they are
// (Qt 6.4's styles cut them at both ends). Before the header is set up: it replaces the view's.
void useElidingHeader(QTableView* view);

// Keeps the columns within the view's width, so that it never scrolls sideways: where their widths (as set,
// or as fitted to their content) add up to more than the viewport, the widest fitted columns give up width
// first, each down to a floor of two letters of its title, their text elided; the stretched column keeps at
// least `stretchPercent` of the width. Applied on every resize of the view.
void keepColumnsWithinWidth(QTableView* view, int stretchPercent = 0);
// The order in which columns give up width: a column of a higher tier (default 0) only once those of the
// lower tiers are at their floors, and then down to minPx (0: two letters of its title; a name that must stay
// whole, a time of day).
void setColumnShrinkTier(QTableView* view, int column, int tier, int minPx = 0);

// A column of low value (coordinates, a second name) that goes out of sight where the view is too narrow for
// every column at its wanted width: the lowest priority first, before any column is elided; it comes back
// when the view is wide enough again. The header's column menu (addColumnMenu) shows it for good, or hides
// any column. Before keepColumnsWithinWidth.
void setColumnDroppable(QTableView* view, int column, int priority);

// A context menu on the header: a check box per column, to show or hide it (a column shown there is never
// dropped for width, one hidden there stays hidden).
void addColumnMenu(QTableView* view);

// A cell whose text is elided shows its whole text as its tooltip (before the model's own tooltip).
void showElidedTextInTooltips(QTableView* view);

} // namespace ocu
