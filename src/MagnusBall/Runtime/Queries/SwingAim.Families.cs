// SwingAim, part: each swing's two adjustable angles and the launch they give (IFamily's four implementations).
// The public inverses are in SwingAim.cs, the solve in SwingAim.Solve.cs.
using MagnusBall.Contact.Swings;

namespace MagnusBall.Queries
{
    public sealed partial class SwingAim
    {
        /// <summary>A racket swing's face tilt (x1) and azimuth (x2).</summary>
        private readonly struct RacketFamily : IFamily<RacketSwing>
        {
            private readonly RacketSwing _swing;
            private readonly LaunchFrame _frame;
            private readonly Vector3d _position, _velocity, _spin;
            private readonly Ball _ball;

            public RacketFamily(in RacketSwing swing, in LaunchFrame frame, in Vector3d position, in Vector3d velocity, in Vector3d spin, Ball ball)
            {
                _swing = swing;
                _frame = frame;
                _position = position;
                _velocity = velocity;
                _spin = spin;
                _ball = ball;
            }

            public bool InRange(double x1, double x2) => Within(x1, -80, 80) && Within(x2, -90, 90);

            public RacketSwing With(double x1, double x2) => _swing.WithFace(x1, x2);

            public SwingLaunch Hit(in RacketSwing swing) => swing.Hit(_ball, _frame, _position, _velocity, _spin);
        }

        /// <summary>A club delivery's dynamic loft (x1) and face angle (x2), the path turned with the face.</summary>
        private readonly struct ClubFamily : IFamily<ClubSwing>
        {
            private readonly ClubSwing _swing;
            private readonly LaunchFrame _frame;
            private readonly Vector3d _position;
            private readonly Ball _ball;
            private readonly double _pathFromFace;

            public ClubFamily(in ClubSwing swing, in LaunchFrame frame, in Vector3d position, Ball ball)
            {
                _swing = swing;
                _frame = frame;
                _position = position;
                _ball = ball;
                _pathFromFace = swing.ClubPathDegrees - swing.FaceAngleDegrees;
            }

            public bool InRange(double x1, double x2) => Within(x1, -10, 80) && Within(x2, -45, 45) && Within(x2 + _pathFromFace, -45, 45);

            public ClubSwing With(double x1, double x2) => new ClubSwing(
                _swing.Speed, x1, _swing.AttackAngleDegrees, x2, x2 + _pathFromFace, _swing.Head, _swing.Restitution, _swing.Friction);

            public SwingLaunch Hit(in ClubSwing swing) => swing.Hit(_ball, _frame, _position);
        }

        /// <summary>A bat swing's path elevation (x1) and azimuth (x2).</summary>
        private readonly struct BatFamily : IFamily<BatSwing>
        {
            private readonly BatSwing _swing;
            private readonly LaunchFrame _frame;
            private readonly Vector3d _position, _velocity, _spin;
            private readonly Ball _ball;

            public BatFamily(in BatSwing swing, in LaunchFrame frame, in Vector3d position, in Vector3d velocity, in Vector3d spin, Ball ball)
            {
                _swing = swing;
                _frame = frame;
                _position = position;
                _velocity = velocity;
                _spin = spin;
                _ball = ball;
            }

            public bool InRange(double x1, double x2) => Within(x1, -45, 45) && Within(x2, -90, 90);

            public BatSwing With(double x1, double x2) => new BatSwing(
                _swing.Speed, _swing.Undercut, x1, x2, _swing.CollisionEfficiency, _swing.Restitution, _swing.Friction);

            public SwingLaunch Hit(in BatSwing swing) => swing.Hit(_ball, _frame, _position, _velocity, _spin);
        }

        /// <summary>A kick's foot path elevation (x1) and azimuth (x2).</summary>
        private readonly struct KickFamily : IFamily<KickSwing>
        {
            private readonly KickSwing _kick;
            private readonly LaunchFrame _frame;
            private readonly Vector3d _position;
            private readonly Ball _ball;

            public KickFamily(in KickSwing kick, in LaunchFrame frame, in Vector3d position, Ball ball)
            {
                _kick = kick;
                _frame = frame;
                _position = position;
                _ball = ball;
            }

            public bool InRange(double x1, double x2) => Within(x1, -45, 60) && Within(x2, -90, 90);

            public KickSwing With(double x1, double x2) => new KickSwing(
                _kick.Speed, _kick.Offset, _kick.Friction, x1, x2, _kick.FootMass, _kick.Restitution);

            public SwingLaunch Hit(in KickSwing kick) => kick.Hit(_ball, _frame, _position);
        }
    }
}
