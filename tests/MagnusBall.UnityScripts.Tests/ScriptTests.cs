using System;
using System.Reflection;
using MagnusBall.Flight;
using MagnusBall.Samples.TennisScene;
using MagnusBall.Samples.TennisScene.Unity;
using MagnusBall.Stepping;
using NUnit.Framework;
using UnityEngine;

namespace MagnusBall.UnityScripts.Tests
{
    /// <summary>
    /// The sample scripts, run on the UnityEngine stub as Unity would run them. The stub only stores values,
    /// so these check the scripts' own logic: frame-rate independence, the predicted line, the camera keys
    /// and the court's geometry.
    /// </summary>
    [TestFixture]
    [NonParallelizable] // the stub's Time and Input are static, as Unity's are
    public class ScriptTests
    {
        [TearDown]
        public void ClearInput() => Input.StubKeysDown.Clear();

        private static void Call(object script, string unityMessage) =>
            script.GetType().GetMethod(unityMessage, BindingFlags.Instance | BindingFlags.NonPublic)!.Invoke(script, null);

        private static (System.Collections.Generic.List<FlightEvent> Touches, Vector3 Drawn, Vector3d Stop) FlyAt(float frameDelta, bool fixedUpdate = false)
        {
            var ball = new TennisBall { stepInFixedUpdate = fixedUpdate };
            var touches = new System.Collections.Generic.List<FlightEvent>();
            Call(ball, "Start"); // builds the model from the inspector defaults and launches
            ball.Touched += touches.Add;
            Time.deltaTime = frameDelta;
            Time.fixedDeltaTime = ball.fixedStep;
            for (int frame = 0; frame < 100_000 && ball.IsFlying; frame++)
            {
                if (fixedUpdate)
                {
                    Call(ball, "FixedUpdate");
                }

                Call(ball, "Update");
            }

            Assert.That(ball.IsFlying, Is.False, "the ball comes to rest");
            Assert.That(touches.Count, Is.GreaterThanOrEqualTo(2), "it bounces on the hard court");
            for (int frame = 0; frame < 3; frame++)
            {
                Call(ball, "Update"); // let the render state come to rest
            }

            return (touches, ball.transform.position, ball.Driver.State.Position);
        }

        [Test]
        public void TheBall_BouncesOnTheSameBits_At30And60And144Fps_AndInFixedUpdate()
        {
            (var reference, Vector3 drawn, Vector3d rest) = FlyAt(1f / 60f);
            foreach ((float delta, bool fixedUpdate) in new[] { (1f / 30f, false), (1f / 144f, false), (0f, true) })
            {
                var touches = FlyAt(delta, fixedUpdate).Touches;
                Assert.That(touches.Count, Is.EqualTo(reference.Count));
                for (int i = 0; i < touches.Count; i++)
                {
                    Assert.That(touches[i].Position, Is.EqualTo(reference[i].Position), $"delta {delta}, touch {i}");
                    Assert.That(touches[i].Time, Is.EqualTo(reference[i].Time), $"delta {delta}, touch {i}");
                }
            }

            // The transform ends where the library says, rounded to float (1e-5 m: float has 24 bits, on numbers of tens of metres).
            Assert.That(FlyAt(1f / 144f).Stop, Is.EqualTo(rest), "where it stops rolling");
            Assert.That(drawn.x, Is.EqualTo(rest.X).Within(1e-5));
            Assert.That(drawn.y, Is.EqualTo(rest.Y).Within(1e-5));
            Assert.That(drawn.z, Is.EqualTo(rest.Z).Within(1e-5));
        }

        [Test]
        public void TheInspectorDefaults_AreTheHeadlessFlatServe_AndLandInTheDeuceBox()
        {
            // The inspector's front/top/left defaults are the flat serve's velocity rounded to 0.01 m/s, so the
            // Unity ball and the headless table's first row must land within a few centimetres of each other.
            FlightEvent landing = FlyAt(1f / 60f).Touches[0];
            var headless = new ShotSimulation(new SceneSettings()).Run(StandardShots.FlatServe, Span<Vector3d>.Empty);
            TestContext.Out.WriteLine($"Unity defaults land at {landing.Position}; headless flat serve at {headless.Landing}");
            // 5 cm: the 0.005 m/s rounding of the inspector's velocity moves a 0.44 s flight by well under that.
            Assert.That(landing.Position.X, Is.EqualTo(headless.Landing.X).Within(0.05));
            Assert.That(landing.Position.Z, Is.EqualTo(headless.Landing.Z).Within(0.05));
            Assert.That(TennisCourt.IsIn(TargetArea.FarDeuceServiceBox, landing.Position.X, landing.Position.Z), Is.True);
        }

        [Test]
        public void TheLine_IsThePathTheBallFlies()
        {
            var ball = new TennisBall();
            Call(ball, "Start");
            var holder = new GameObject();
            LineRenderer renderer = holder.AddComponent<LineRenderer>();
            TrajectoryLine line = holder.AddComponent<TrajectoryLine>();
            line.ball = ball;
            Call(line, "Awake");
            Call(line, "LateUpdate");

            Assert.That(renderer.positionCount, Is.GreaterThan(10));
            Vector3 first = renderer.GetPosition(0), last = renderer.GetPosition(renderer.positionCount - 1);
            Assert.That(first.x, Is.EqualTo(ball.servePosition.x));
            Assert.That(first.y, Is.EqualTo(ball.servePosition.y));

            FlightEvent landing = FlyAt(1f / 60f).Touches[0];
            // The line ends at the landing the ball then flies to (float rounding only: 1e-5 m).
            Assert.That(last.x, Is.EqualTo(landing.Position.X).Within(1e-5));
            Assert.That(last.z, Is.EqualTo(landing.Position.Z).Within(1e-5));
        }

        [Test]
        public void F1_ShowsTheSecondaryCamera_F2_ThePrimary()
        {
            var primary = new Camera();
            var secondary = new Camera();
            var cameras = new CameraSwitch { primaryCamera = primary, secondaryCamera = secondary };
            Call(cameras, "Start");
            Assert.That((primary.enabled, secondary.enabled), Is.EqualTo((true, false)));

            Input.StubKeysDown.Add(KeyCode.F1);
            Call(cameras, "Update");
            Assert.That((primary.enabled, secondary.enabled), Is.EqualTo((false, true)));

            Input.StubKeysDown.Clear();
            Input.StubKeysDown.Add(KeyCode.F2);
            Call(cameras, "Update");
            Assert.That((primary.enabled, secondary.enabled), Is.EqualTo((true, false)));
        }

        [Test]
        public void TheCourt_IsBuiltToItfDimensions()
        {
            var holder = new GameObject();
            CourtBuilder court = holder.AddComponent<CourtBuilder>();
            court.Build();
            var parts = new System.Collections.Generic.List<GameObject>();
            for (int i = 0; i < holder.transform.childCount; i++)
            {
                parts.Add(holder.transform.GetChild(i).gameObject);
            }

            GameObject surface = parts.Find(p => p.name == "court")!;
            Assert.That(surface.transform.localScale.x, Is.EqualTo(23.77f));
            Assert.That(surface.transform.localScale.z, Is.EqualTo(10.97f));

            // The net: 0.914 m in the middle, 1.07 m at the posts (within half a slice of the sloping cord: 1 cm).
            var net = parts.FindAll(p => p.name == "net");
            float lowest = float.MaxValue, highest = 0;
            foreach (GameObject slice in net)
            {
                lowest = Math.Min(lowest, slice.transform.localScale.y);
                highest = Math.Max(highest, slice.transform.localScale.y);
            }

            Assert.That(lowest, Is.EqualTo(0.914f).Within(0.01));
            Assert.That(highest, Is.EqualTo(1.07f).Within(0.01));
            GameObject post = parts.Find(p => p.name == "net post")!;
            Assert.That(Math.Abs(post.transform.localPosition.z), Is.EqualTo(10.97f / 2 + 0.914f).Within(1e-5));

            // Every line lies inside the doubles outline (dimensions are to the lines' outer edges).
            foreach (GameObject line in parts.FindAll(p => p.name.Contains("line") || p.name.Contains("mark")))
            {
                Vector3 c = line.transform.localPosition, s = line.transform.localScale;
                Assert.That(Math.Abs(c.x) + s.x / 2, Is.LessThanOrEqualTo(23.77f / 2 + 1e-4), line.name);
                Assert.That(Math.Abs(c.z) + s.z / 2, Is.LessThanOrEqualTo(10.97f / 2 + 1e-4), line.name);
            }
        }
    }
}
