using System;
using MagnusBall.Integration;
using NUnit.Framework;

namespace MagnusBall.Tests.Behavior
{
    /// <summary>
    /// The signs of the Magnus effect, in three frames: right-handed z-up (the thesis), left-handed y-up
    /// (Unity) and right-handed y-up (Godot). The same physical shot is described in each frame's own numbers.
    /// </summary>
    [TestFixture]
    public class SpinSignTests
    {
        /// <summary>A frame: where "forward", "left" and "up" point, and its handedness.</summary>
        public sealed class Frame
        {
            public Frame(string name, Vector3d forward, Vector3d left, Vector3d up)
            {
                Name = name;
                Forward = forward;
                Left = left;
                Up = up;
            }

            public string Name { get; }
            public Vector3d Forward { get; }
            public Vector3d Left { get; }
            public Vector3d Up { get; }

            /// <summary>+1 for right-handed (forward x left = up), -1 for left-handed.</summary>
            public double Handedness => Vector3d.Dot(Vector3d.Cross(Forward, Left), Up);

            public Vector3d Map(double forward, double left, double up) => Forward * forward + Left * left + Up * up;

            public override string ToString() => Name;
        }

        public static readonly Frame[] Frames =
        {
            // Thesis: x downrange, y left, z up (right-handed).
            new Frame("z-up right-handed", Vector3d.UnitX, Vector3d.UnitY, Vector3d.UnitZ),
            // Unity: x right, y up, z forward (left-handed).
            new Frame("Unity y-up left-handed", Vector3d.UnitZ, -Vector3d.UnitX, Vector3d.UnitY),
            // Godot: x right, y up, -z forward (right-handed).
            new Frame("Godot y-up right-handed", -Vector3d.UnitZ, -Vector3d.UnitX, Vector3d.UnitY),
        };

        private const double Rate = 150; // rad/s, about 24 rev/s

        private static (double Forward, double Left) Land(Frame frame, Func<Vector3d, Vector3d, Vector3d> spin)
        {
            FlightModel model = Shots.StepanekTennis(frame.Up * -Gravity.Standard);
            Vector3d velocity = frame.Map(28, 0, 6);
            var state = new FlightState(frame.Map(0, 0, 1), velocity, spin(velocity, frame.Up));
            Vector3d landing = Shots.Landing(model, RungeKutta4.Instance, state, frame.Up, 1.0 / 240);
            return (Vector3d.Dot(landing, frame.Forward), Vector3d.Dot(landing, frame.Left));
        }

        [TestCaseSource(nameof(Frames))]
        public void Topspin_LandsShorter_BackspinLonger_ThanNoSpin(Frame frame)
        {
            double flat = Land(frame, (v, up) => Vector3d.Zero).Forward;
            double top = Land(frame, (v, up) => Spin.Topspin(v, up, Rate)).Forward;
            double back = Land(frame, (v, up) => Spin.Backspin(v, up, Rate)).Forward;
            TestContext.Out.WriteLine($"{frame}: topspin {top:F3} m, flat {flat:F3} m, backspin {back:F3} m");
            Assert.That(top, Is.LessThan(flat - 1.0));
            Assert.That(back, Is.GreaterThan(flat + 1.0));
        }

        [TestCaseSource(nameof(Frames))]
        public void SpinTowardLeft_CurvesLeft_TowardRight_CurvesRight(Frame frame)
        {
            double left = Land(frame, (v, up) => Spin.Toward(v, frame.Left, Rate)).Left;
            double right = Land(frame, (v, up) => Spin.Toward(v, -frame.Left, Rate)).Left;
            double flat = Land(frame, (v, up) => Vector3d.Zero).Left;
            Assert.That(flat, Is.EqualTo(0).Within(1e-12));
            Assert.That(left, Is.GreaterThan(0.5));
            Assert.That(right, Is.LessThan(-0.5));
            Assert.That(left, Is.EqualTo(-right).Within(1e-9), "mirror-symmetric shots");
        }

        [Test]
        public void TheSameShot_LandsAtTheSamePoint_InEveryFrame()
        {
            Func<Vector3d, Vector3d, Vector3d> topspinCurlingLeft = (v, up) =>
                Spin.Topspin(v, up, Rate) + Spin.Toward(v, Vector3d.Cross(up, v).NormalizedOrZero(), 60);
            (double Forward, double Left) reference = Land(Frames[0], topspinCurlingLeft);
            foreach (Frame frame in Frames)
            {
                // Spin.Toward's cross(up, v) is "left" only in a right-handed frame; in a left-handed one it is right.
                (double Forward, double Left) landing = Land(frame, topspinCurlingLeft);
                Assert.That(landing.Forward, Is.EqualTo(reference.Forward).Within(1e-9), frame.Name);
                Assert.That(landing.Left, Is.EqualTo(reference.Left * frame.Handedness).Within(1e-9), frame.Name);
            }
        }

        [Test]
        public void UnitySpin_IsTheNegatedMirrorOfTheRightHandedSpin()
        {
            // The same physical topspin, built by effect in each frame: in Unity's left-handed numbers the
            // rotation vector follows the left-hand rule, so it is the mirror image with the sign flipped.
            Frame zUp = Frames[0], unity = Frames[1];
            Vector3d wZ = Spin.Topspin(zUp.Map(28, 0, 6), zUp.Up, Rate);
            Vector3d wU = Spin.Topspin(unity.Map(28, 0, 6), unity.Up, Rate);
            Vector3d mirrored = unity.Map(Vector3d.Dot(wZ, zUp.Forward), Vector3d.Dot(wZ, zUp.Left), Vector3d.Dot(wZ, zUp.Up));
            Assert.That(Vector3d.Distance(wU, -mirrored), Is.LessThan(1e-12));
        }
    }
}
