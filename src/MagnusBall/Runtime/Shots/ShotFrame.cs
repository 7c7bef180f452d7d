using System;

namespace MagnusBall.Shots
{
    /// <summary>
    /// Where a shot is described: an origin on the ground, up, forward (toward the target) and right (the right of a
    /// player facing forward). Every game-term angle and distance of <see cref="MagnusBall.Shots"/> is measured in
    /// this frame: direction and sidespin positive to the right, heights along up, distances along forward.
    /// </summary>
    /// <remarks>
    /// Right is given, not derived, because which of up x forward and forward x up is a player's right depends on
    /// the engine's handedness: <see cref="ZUp"/> (right-handed, x forward) has right = -y, Unity's left-handed
    /// <see cref="YUp"/> (z forward) has right = +x, Godot's right-handed y-up frame (forward -z) has right = +x.
    /// The frame keeps only the side of <c>right</c>: it is made exactly perpendicular to up and forward.
    /// </remarks>
    public readonly struct ShotFrame
    {
        private readonly Vector3d _origin;

        /// <summary>Creates a frame.</summary>
        /// <param name="up">Up (for example -gravity); finite, non-zero.</param>
        /// <param name="forward">Toward the target; finite, not parallel to up (its part across up is used).</param>
        /// <param name="right">The right of a player facing forward; finite, not in the plane of up and forward (only its side is used).</param>
        /// <param name="origin">The frame's origin on the ground, m (for example the centre of a tennis baseline).</param>
        /// <exception cref="ArgumentException">A vector is zero or not finite, forward is parallel to up, or right lies in the plane of up and forward.</exception>
        public ShotFrame(Vector3d up, Vector3d forward, Vector3d right, Vector3d origin = default)
        {
            Require.Finite(origin, nameof(origin));
            Require.NonZero(right, nameof(right));
            var frame = new LaunchFrame(up, forward);
            double side = Vector3d.Dot(right.NormalizedOrZero(), frame.Side);
            if (!(Math.Abs(side) > 1e-9))
            {
                throw new ArgumentException(
                    $"right must point to one side of the plane of up and forward (for Unity's y-up frame, +x); got right {right}, up {up}, forward {forward}.",
                    nameof(right));
            }

            Up = frame.Up;
            Forward = frame.Forward;
            Right = side > 0 ? frame.Side : -frame.Side;
            _origin = origin;
        }

        /// <summary>z up, x forward, right -y (a right-handed frame, the thesis's), origin at zero.</summary>
        public static ShotFrame ZUp => new ShotFrame(Vector3d.UnitZ, Vector3d.UnitX, -Vector3d.UnitY);

        /// <summary>Unity's frame: y up, z forward, right +x (left-handed), origin at zero.</summary>
        public static ShotFrame YUp => new ShotFrame(Vector3d.UnitY, Vector3d.UnitZ, Vector3d.UnitX);

        /// <summary>Unit up.</summary>
        public Vector3d Up { get; }

        /// <summary>Unit forward, perpendicular to up.</summary>
        public Vector3d Forward { get; }

        /// <summary>Unit right, perpendicular to up and forward.</summary>
        public Vector3d Right { get; }

        /// <summary>The world position <paramref name="forwardMetres"/> ahead, <paramref name="rightMetres"/> right and <paramref name="upMetres"/> up from the origin.</summary>
        /// <param name="forwardMetres">Distance along forward, m; finite.</param>
        /// <param name="rightMetres">Distance along right, m; finite.</param>
        /// <param name="upMetres">Height along up, m; finite.</param>
        /// <exception cref="ArgumentOutOfRangeException">A distance is not finite.</exception>
        public Vector3d At(double forwardMetres, double rightMetres, double upMetres)
        {
            Require.Finite(forwardMetres, nameof(forwardMetres));
            Require.Finite(rightMetres, nameof(rightMetres));
            Require.Finite(upMetres, nameof(upMetres));
            return _origin + Forward * forwardMetres + Right * rightMetres + Up * upMetres;
        }

        internal bool IsDefault => Up.LengthSquared == 0;

        /// <summary>The frame coordinates (forward, right, up) of a world position.</summary>
        internal Vector3d ToFrame(in Vector3d world)
        {
            Vector3d d = world - _origin;
            return new Vector3d(Vector3d.Dot(d, Forward), Vector3d.Dot(d, Right), Vector3d.Dot(d, Up));
        }

        /// <summary>The frame components (forward, right, up) of a world direction or velocity.</summary>
        internal Vector3d VectorToFrame(in Vector3d world) =>
            new Vector3d(Vector3d.Dot(world, Forward), Vector3d.Dot(world, Right), Vector3d.Dot(world, Up));

        /// <inheritdoc />
        public override string ToString() => $"ShotFrame(up={Up}, forward={Forward}, right={Right}, origin={_origin})";
    }
}
