using System;

namespace MagnusBall.Queries
{
    /// <summary>Which of a target's two solutions at one speed an aim solve returns: the flat one or the lob.</summary>
    public enum AimArc
    {
        /// <summary>The lower elevation (a drive, a flat kick): the lowest solution within the solver's limits.</summary>
        Low = 0,

        /// <summary>The higher elevation (a lob, a chip over a wall): the highest solution within the solver's limits.</summary>
        High = 1,
    }

    /// <summary>
    /// A wall or net between the launch point and the target, as a player sees it: a vertical plane across the way at
    /// <see cref="DistanceMeters"/> from the launch point (measured horizontally along the direction to the target) whose top
    /// is <see cref="TopHeightMeters"/> above the ground. A launch clears it when the ball's bottom (its centre less its
    /// radius) passes above the top where the ball crosses the plane. The default value is no obstacle.
    /// </summary>
    public readonly struct AimObstacle
    {
        /// <summary>Creates an obstacle.</summary>
        /// <param name="distanceMeters">Horizontal distance from the launch point along the direction to the target, m; finite and &gt; 0 (and, when solving, short of the target).</param>
        /// <param name="topHeightMeters">Height of the obstacle's top above the ground, m; finite (a free kick's wall 2.3 m with a jump, a tennis net 0.914 m).</param>
        /// <exception cref="ArgumentException">An argument is out of range; the message names it.</exception>
        public AimObstacle(double distanceMeters, double topHeightMeters)
        {
            DistanceMeters = Require.Positive(distanceMeters, nameof(distanceMeters));
            TopHeightMeters = Require.Finite(topHeightMeters, nameof(topHeightMeters));
        }

        /// <summary>Horizontal distance from the launch point along the direction to the target, m (0: no obstacle).</summary>
        public double DistanceMeters { get; }

        /// <summary>Height of the top above the ground, m; the ball's bottom must pass above it.</summary>
        public double TopHeightMeters { get; }

        /// <summary>True for the default value (no obstacle).</summary>
        internal bool IsNone => DistanceMeters == 0;
    }
}
