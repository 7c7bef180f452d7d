using System;
using MagnusBall.Contact;
using MagnusBall.Tests.Behavior;

namespace MagnusBall.Tests.Contact
{
    /// <summary>
    /// A bounce in the vertical plane of travel, described as Cross does (speed, angle below the surface,
    /// topspin positive) and read back the same way, in any frame.
    /// </summary>
    public readonly struct Court
    {
        public Court(SpinSignTests.Frame frame)
        {
            Frame = frame;
        }

        public SpinSignTests.Frame Frame { get; }

        /// <summary>The topspin axis for a ball moving forward: up x forward in any handedness (see SpinSignTests).</summary>
        public Vector3d TopspinAxis => Vector3d.Cross(Frame.Up, Frame.Forward);

        /// <summary>The sidespin axis: spin about the direction of travel (rpm positive = right-hand rule about forward in a right-handed frame).</summary>
        public Vector3d ForwardAxis => Frame.Forward * Frame.Handedness;

        public Vector3d Velocity(double speed, double angleDegrees)
        {
            double a = angleDegrees * Math.PI / 180;
            return Frame.Map(speed * Math.Cos(a), 0, -speed * Math.Sin(a));
        }

        public BounceOutcome Bounce(IBounceModel model, Ball ball, double speed, double angleDegrees, double topspinRpm, double sidespinRpm = 0) =>
            model.Bounce(
                ball,
                Frame.Up,
                Velocity(speed, angleDegrees),
                TopspinAxis * Spin.FromRpm(topspinRpm) + ForwardAxis * Spin.FromRpm(sidespinRpm));

        public double Forward(in Vector3d v) => Vector3d.Dot(v, Frame.Forward);

        public double Left(in Vector3d v) => Vector3d.Dot(v, Frame.Left);

        public double Up(in Vector3d v) => Vector3d.Dot(v, Frame.Up);

        public double Speed(in BounceOutcome o) => o.Velocity.Length;

        /// <summary>Outgoing angle above the surface in the vertical plane, degrees.</summary>
        public double AngleDegrees(in BounceOutcome o) => Math.Atan2(Up(o.Velocity), Forward(o.Velocity)) * 180 / Math.PI;

        public double TopspinRpm(in BounceOutcome o) => Spin.ToRpm(Vector3d.Dot(o.AngularVelocity, TopspinAxis));

        public double SidespinRpm(in BounceOutcome o) => Spin.ToRpm(Vector3d.Dot(o.AngularVelocity, ForwardAxis));

        public override string ToString() => Frame.Name;

        public static readonly Court ZUp = new Court(SpinSignTests.Frames[0]);

        public static readonly Court Unity = new Court(SpinSignTests.Frames[1]);

        public static readonly Court Godot = new Court(SpinSignTests.Frames[2]);

        public static Court[] All => new[] { ZUp, Unity, Godot };
    }
}
