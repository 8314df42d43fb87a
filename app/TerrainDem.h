#pragma once
// The site's terrain from a DEM (GeoTIFF or any raster GDAL reads), configured as
// `"terrain": {"dem": "<file>"}` (docs/site-config.md). The DEM may be in any CRS GDAL knows (a UTM zone,
// WGS84 degrees...): it is resampled bilinearly onto a regular grid in the site's ENU frame, at most
// maxSide x maxSide samples, for the 3D view's surface. NoData samples take the mean of the valid ones.
#include "protocols/common/GeoFrame.h"
#include "protocols/common/Result.h"
#include "widgets/view3d/Scene3D.h"

#include <string>

namespace ocu {

// Error text (file, driver, CRS) when the DEM cannot be used; the 3D view then keeps a flat ground.
Result<TerrainGrid3D> loadTerrainDem(const std::string& path, const GeoFrame& frame, int maxSide = 256);

} // namespace ocu
