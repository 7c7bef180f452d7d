using System;
using System.Reflection;
using MagnusBall.Contact.Swings;
using MagnusBall.Samples.TennisScene;
using MagnusBall.Samples.TennisScene.Scripts;
using NUnit.Framework;
using UnityEngine;
using static MagnusBall.UnityScripts.Tests.UnityLoop;

namespace MagnusBall.UnityScripts.Tests
{
    /// <summary>
    /// The sample's inspector sets the swing, not the launch: TennisBall's swing fields build a RacketSwing, the
    /// library's impact law gives the launch the flight starts from, and the inspector's ranges are the swing's.
    /// </summary>
    [TestFixture]
    [NonParallelizable] // the stub's Time is static, as Unity's is
    public class InspectorSwingTests
    {
        private static readonly ShotSimulation Simulation = new ShotSimulation(new SceneSettings());

        private static TennisBall NewBall()
        {
            var holder = new GameObject("ball");
            TennisBall ball = Add<TennisBall>(holder);
            ball.launchOnStart = false;
            Call(ball, "Start");
            return ball;
        }

        private static Vector3d Landing(TennisBall ball)
        {
            // The flight the component starts, run by the scene's simulation from the driver's start state.
            MagnusBall.FlightState start = ball.Driver.State;
            TennisShot shot = TennisShot.FromLaunch("inspector", start.Position, start.Velocity, start.AngularVelocity, TargetArea.FarDeuceServiceBox);
            ShotReport report = Simulation.Run(shot, Span<Vector3d>.Empty);
            Assert.That(report.Landed, Is.True);
            return report.Landing;
        }

        [Test]
        public void ByDefault_TheInspectorSwing_IsTheScenesFlatServe_AndLaunchesThroughTheImpactLaw()
        {
            TennisBall ball = NewBall();
            Assert.That(ball.launchBy, Is.EqualTo(LaunchInput.Swing));
            Assert.That(ball.Launch(), Is.True);
            Assert.That(ball.IsFlying, Is.True);

            // The driver starts from exactly what RacketSwing.Hit gives for the inspector's fields.
            TennisSwing swing = ball.Swing();
            SwingLaunch expected = swing.Swing.Hit(ball.Settings.Ball, TennisSwing.Frame, swing.Start, swing.IncomingVelocity, swing.IncomingSpin);
            Assert.That(ball.Driver.State.Velocity, Is.EqualTo(expected.Velocity));
            Assert.That(ball.Driver.State.AngularVelocity, Is.EqualTo(expected.AngularVelocity));
            Assert.That(ball.LastSwingLaunch.Velocity, Is.EqualTo(expected.Velocity));

            // And the defaults are the scene's flat serve made by a swing: the inspector's floats round StandardSwings'
            // doubles by at most 4e-7 deg (6.845f), micrometres after 18 m; the stored swings land within 5 mm of the
            // launch-defined shots (SwingShotTests), so the inspector's serve must too.
            TennisShot standard = StandardShots.FlatServe;
            ShotReport today = Simulation.Run(standard, Span<Vector3d>.Empty);
            double miss = Vector3d.Distance(Landing(ball), today.Landing);
            TestContext.Out.WriteLine($"inspector flat serve lands {miss * 1000:F3} mm from the standard flat serve");
            Assert.That(miss, Is.LessThan(5e-3));
        }

        [Test]
        public void TheSwingFields_SetTheLaunch()
        {
            TennisBall ball = NewBall();
            ball.incomingVelocity = new Vector3(-14f, -1f, 0f);
            ball.servePosition = new Vector3(-12f, 1f, 0f);
            ball.swingAzimuth = 0f;
            ball.faceTilt = 0f;
            ball.racketSpeed = 26f;

            ball.pathElevation = 0f;
            ball.Launch();
            double flatTopspin = ball.LastSwingLaunch.LaunchSpin.Topspin;
            ball.pathElevation = 40f;
            ball.Launch();
            double steepTopspin = ball.LastSwingLaunch.LaunchSpin.Topspin;
            Assert.That(steepTopspin, Is.GreaterThan(flatTopspin + 100), "a low-to-high path adds topspin (rad/s)");

            double centreSpeed = ball.LastSwingLaunch.Speed;
            ball.impactPoint = StringBedPoint.Tip;
            ball.Launch();
            Assert.That(ball.LastSwingLaunch.Speed, Is.LessThan(centreSpeed), "the tip (ACOR 0.10) is slower than the centre (0.45)");
            Assert.That(ball.Swing().Swing.ApparentRestitution, Is.EqualTo(RacketSwing.TipRestitution));

            ball.impactPoint = StringBedPoint.Centre;
            ball.faceTurn = 20f;
            ball.Launch();
            Assert.That(Math.Abs(ball.LastSwingLaunch.LaunchSpin.Sidespin), Is.GreaterThan(10), "a face turned from the path gives sidespin");

            // Launching by launch ignores the swing and uses the launch fields.
            ball.launchBy = LaunchInput.Launch;
            ball.Launch();
            Assert.That(ball.Driver.State.Velocity, Is.EqualTo(ball.LaunchState().Velocity));
            Assert.That(ball.LastSwingLaunch.IsHit, Is.False);
        }

        [Test]
        public void ASwingThatMissesTheBall_LaunchesNothing()
        {
            TennisBall ball = NewBall();
            ball.incomingVelocity = new Vector3(40f, 0f, 0f); // moving away from a racket swung forward at 34 m/s
            ball.swingAzimuth = 0f;
            ball.faceTilt = 0f;
            Assert.That(ball.Launch(), Is.False);
            Assert.That(ball.IsFlying, Is.False);
            Assert.That(ball.Driver, Is.Null, "no flight was started");
        }

        [Test]
        public void ABadSwingField_IsRefused_NamingIt_AndTheFlyingBallIsLeftAlone()
        {
            TennisBall ball = NewBall();
            Assert.That(ball.Launch(), Is.True);
            MagnusBall.FlightState before = ball.Driver.State;
            SceneSettings settings = ball.Settings;
            ball.racketSpeed = float.NaN;
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => ball.Launch())!;
            Assert.That(e.ParamName, Is.EqualTo("speed"));
            ball.racketSpeed = 34f;
            ball.faceTurn = 75f;
            e = Assert.Throws<ArgumentOutOfRangeException>(() => ball.Launch())!;
            Assert.That(e.ParamName, Is.EqualTo("faceTurnDegrees"));
            Assert.That(ball.IsFlying, Is.True);
            Assert.That(ball.Driver.State, Is.EqualTo(before));
            Assert.That(ball.Settings, Is.SameAs(settings));
        }

        [Test]
        public void ABadLaunchField_ChangesNothing_NotEvenTheSettings()
        {
            // A review found Launch configuring the flight and keeping the new settings before the start was refused.
            TennisBall ball = NewBall();
            Assert.That(ball.Launch(), Is.True);
            MagnusBall.FlightState before = ball.Driver.State;
            SceneSettings settings = ball.Settings;
            ShotSimulation simulation = ball.Simulation;
            double step = ball.Flight.FixedStep;
            SwingLaunch swing = ball.LastSwingLaunch;

            ball.fixedStep = 1f / 120f; // a good new setting, with a bad launch field
            ball.launchBy = LaunchInput.Launch;
            ball.spinInput = SpinInput.Components;
            ball.spinComponents = new Vector3(float.NaN, 0f, 0f); // refused by the flight, after the settings were built
            var e = Assert.Throws<ArgumentException>(() => ball.Launch())!;
            Assert.That(e.ParamName, Is.EqualTo("start"));
            Assert.That(ball.IsFlying, Is.True);
            Assert.That(ball.Driver.State, Is.EqualTo(before));
            Assert.That(ball.Flight.FixedStep, Is.EqualTo(step), "the flight's configuration is unchanged");
            Assert.That(ball.Settings, Is.SameAs(settings));
            Assert.That(ball.Simulation, Is.SameAs(simulation));
            Assert.That(ball.LastSwingLaunch.Velocity, Is.EqualTo(swing.Velocity));

            ball.spinComponents = new Vector3(0f, 0f, -200f);
            Assert.That(ball.Launch(), Is.True);
            Assert.That(ball.Flight.FixedStep, Is.EqualTo((double)(1f / 120f)), "a good launch takes the new settings");
            Assert.That(ball.Settings, Is.Not.SameAs(settings));
        }

        [Test]
        public void TheInspectorsRanges_AreTheSwingsRanges()
        {
            // Every [Range] on a swing field is inside what RacketSwing accepts (so the inspector's sliders cannot make a
            // refused swing), and the angle sliders span RacketSwing's whole range.
            var expected = new (string Field, float Min, float Max)[]
            {
                ("racketSpeed", 1f, 60f), ("pathElevation", -80f, 80f), ("faceTilt", -80f, 80f), ("faceTurn", -60f, 60f), ("swingAzimuth", -90f, 90f),
            };
            foreach ((string field, float min, float max) in expected)
            {
                UnityEngine.RangeAttribute range = typeof(TennisBall).GetField(field, BindingFlags.Public | BindingFlags.Instance)!.GetCustomAttribute<UnityEngine.RangeAttribute>()!;
                Assert.That(range, Is.Not.Null, field);
                Assert.That((range.min, range.max), Is.EqualTo((min, max)), field);
                foreach (float value in new[] { range.min, range.max })
                {
                    TennisBall ball = NewBall();
                    typeof(TennisBall).GetField(field)!.SetValue(ball, value);
                    Assert.DoesNotThrow(() => ball.Swing(), $"{field} = {value}");
                }
            }

            TennisBall b = NewBall();
            b.pathElevation = 80.001f;
            Assert.Throws<ArgumentOutOfRangeException>(() => b.Swing());
        }
    }
}
