// Trajectory panel: side view (downrange vs height) and top view (downrange vs lateral) of
// the shot, coloured by phase, with the replay ball marked. The mapping from metres to plot
// pixels is plain logic (tested); drawing uses ImGui's draw list.
#pragma once

#include "physics/trajectory.hpp"

namespace sweetspot {

/// A linear map from a rectangle in metres to a rectangle in pixels, with equal scale on
/// both axes when `keep_aspect` so the side view shows true launch and landing angles.
struct PlotMap {
  double x0 = 0.0, y0 = 0.0;   ///< metres at the plot's lower-left corner
  double scale = 1.0;          ///< px per metre
  double px0 = 0.0, py0 = 0.0; ///< pixel position of the lower-left corner (y grows downwards)

  double to_px_x(double x) const { return px0 + (x - x0) * scale; }
  double to_px_y(double y) const { return py0 - (y - y0) * scale; }
};

enum class PlotView { Side, Top };

/// Fits the whole trajectory into a `width`×`height` pixel box whose lower-left corner is at
/// (px0, py0), with a margin. Side view: horizontal = x (downrange), vertical = y (height).
/// Top view: horizontal = x, vertical = -z, i.e. seen from above with the target to the
/// screen's right, a ball that goes right of the target line (+z) appears below the line.
/// The plotted "y" of a top-view point is therefore -z; use plot_y() for either view.
PlotMap fit_plot(const ShotTrajectory& shot, PlotView view, double px0, double py0, double width,
                 double height);

/// Draws the panel's two plots into the current ImGui window, marking the ball at
/// replay time `t`.
inline double plot_y(const Vec3& p, PlotView view) { return view == PlotView::Side ? p.y() : -p.z(); }

void draw_trajectory_plots(const ShotTrajectory& shot, double t);

}  // namespace sweetspot
