using System;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Threading.Tasks;
using MagnusBall.Aerodynamics;
using MagnusBall.DeterminismCheck;
using MagnusBall.Flight;
using MagnusBall.Integration;
using MagnusBall.Presets;
using MagnusBall.Queries;
using Microsoft.Playwright;
using NUnit.Framework;

namespace MagnusBall.Playground.Tests
{
    /// <summary>
    /// The playground in a real browser (Debian's Chromium): the numbers it shows are the library's to the last bit
    /// (flown here on CoreCLR, written out with the library's public API, not with the page's code), its self-test hash
    /// is CoreCLR's, the drawing follows the inputs, a refused input says why, and the page is usable narrow.
    /// </summary>
    [TestFixture]
    public sealed class PlaygroundTests
    {
        /// <summary>Every test's pages: no uncaught error, no console error, no Blazor error bar; then closed.</summary>
        [TearDown]
        public Task NoPageReportedAnError() => PlaygroundHost.CloseAllAsync();

        private static double ValueOf(string text) => double.Parse(text, NumberStyles.Float, CultureInfo.InvariantCulture);

        private static async Task<double> CellValue(IPage page, string selector) =>
            ValueOf(await page.Locator(selector + " [data-value]").First.GetAttributeAsync("data-value") ?? "NaN");

        [Test]
        public async Task DefaultShot_IsTheLibrarysFlight_BitForBit()
        {
            IPage page = await PlaygroundHost.OpenAsync();
            await page.WaitForSelectorAsync("#path-side");

            // The tennis scene's shot, written out here: 30 m/s, 6 deg up from 1 m, 1200 rpm topspin, the preset in
            // 15 degC air at sea level with 50 % humidity, RK4 at 1/240 s, landing located on the step's Hermite.
            FlightModel model = SportPresets.Tennis.CreateModel(Air.AtAltitude(0, 15, 0.5, new Vector3d(0, 0, 0)), Gravity.ZUp);
            var frame = new LaunchFrame(Vector3d.UnitZ, Vector3d.UnitX);
            Vector3d direction = frame.Direction(6 * (Math.PI / 180), 0);
            var start = new FlightState(new Vector3d(0, 0, 1), direction * 30, new LaunchSpin(Spin.FromRpm(1200)).AngularVelocity(direction, frame));
            var net = new Plane(new Vector3d(11.885, 0, 0), Vector3d.UnitX);
            Prediction p = new TrajectoryPredictor(model, RungeKutta4.Instance, 1.0 / 240, FlightEventSet.ForModel(model, net))
                .Predict(start, 8, Span<Vector3d>.Empty);
            Assert.That(p.Stopped, Is.True);

            Assert.That(await CellValue(page, "#row-landing-x td:nth-child(2)"), Is.EqualTo(p.EndState.Position.X), "landing x, to the bit");
            Assert.That(await CellValue(page, "#row-flight-time td:nth-child(2)"), Is.EqualTo(p.EndState.Time), "flight time, to the bit");
            Assert.That(await CellValue(page, "#row-evaluations td:nth-child(2)"), Is.EqualTo(p.DerivativeEvaluations));
            Assert.That(await page.Locator("#row-outcome td").First.InnerTextAsync(), Is.EqualTo("in (singles court)"));
        }

        /// <summary>Each sport's own shot, judged against its court, goal, plate or ring.</summary>
        [TestCase("soccer", "goal")]
        [TestCase("baseball", "strike")]
        [TestCase("basketball", "swish: through the ring")]
        [TestCase("table-tennis", "on the table")]
        [TestCase("golf", "on the fairway")]
        public async Task EachSportsShot_IsJudgedInItsTerms(string preset, string outcome)
        {
            var clock = System.Diagnostics.Stopwatch.StartNew();
            IPage page = await PlaygroundHost.OpenAsync($"?preset={preset}");
            await page.WaitForSelectorAsync("#path-side");
            TestContext.Out.WriteLine($"{preset}: loaded and flown (with the no-spin shot and both references) in {clock.ElapsedMilliseconds} ms");
            Assert.That(await page.Locator("#row-outcome td").First.InnerTextAsync(), Is.EqualTo(outcome));
            Assert.That(await page.InputValueAsync("#in-preset"), Is.EqualTo(preset));
        }

        [Test]
        public async Task CrossAngles_AreTheLibrarysAngles_BitForBit()
        {
            IPage page = await PlaygroundHost.OpenAsync();
            await page.ClickAsync("#run-cross");
            await page.WaitForSelectorAsync("#cross-table");

            // Cross (2011): a 57 g, 33 mm ball at 30 m/s from 1 m, air 1.21 kg/m^3, Stepanek's laws, RK4 at 1/240 s.
            var model = new FlightModel(new Ball(0.057, 0.033), new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance);
            var solver = new AimSolver(model, RungeKutta4.Instance, 1.0 / 240, Plane.Ground(model));
            var from = new Vector3d(0, 0, 1);
            var net = new Plane(new Vector3d(11.885, 0, 0), Vector3d.UnitX);
            var topspin = new LaunchSpin(Spin.FromRevolutionsPerSecond(20));
            double[] expected =
            {
                solver.MinimumElevationToClear(from, 30, 0, LaunchSpin.None, net, 0.914).ElevationDegrees,
                solver.ElevationToReach(from, 30, LaunchSpin.None, new Vector3d(23.77, 0, 0)).ElevationDegrees,
                solver.MinimumElevationToClear(from, 30, 0, topspin, net, 0.914).ElevationDegrees,
                solver.ElevationToReach(from, 30, topspin, new Vector3d(23.77, 0, 0)).ElevationDegrees,
            };
            for (int i = 0; i < 4; i++)
            {
                Assert.That(await CellValue(page, $"#cross-{i} td:nth-child(3)"), Is.EqualTo(expected[i]), $"case {i}");
            }

            await page.ClickAsync("#run-freekicks");
            await page.WaitForSelectorAsync("#freekick-table");
            double[] across = FreeKicksAcross();
            for (int i = 0; i < 3; i++)
            {
                Assert.That(await CellValue(page, $"#kick-{i} td:nth-child(2)"), Is.EqualTo(across[i]), $"kick {i}");
            }

            // Javorova & Ivanov: only the middle kick scores.
            Assert.That(await page.Locator("#kick-1 td:nth-child(4)").InnerTextAsync(), Is.EqualTo("goal"));
            Assert.That(await page.Locator("#kick-0 td:nth-child(4)").InnerTextAsync(), Does.StartWith("lands short"));
            Assert.That(await page.Locator("#kick-2 td:nth-child(4)").InnerTextAsync(), Is.EqualTo("misses the frame"));
        }

        /// <summary>Javorova &amp; Ivanov's three kicks as tests/MagnusBall.Tests/Validation/FreeKickTests flies them: across at the goal line, m.</summary>
        private static double[] FreeKicksAcross()
        {
            var ball = new Ball(0.425, 0.11, Ball.ThinShellInertiaFactor);
            var model = new FlightModel(ball, new Air(1.21), Gravity.ZUp, GoffCarreSoccerDrag.Instance, PiecewiseLinearLift.SoccerGoffCarre);
            var start = new Vector3d(0, 0, 0.11);
            var ground = new Plane(start, Vector3d.UnitZ);
            var target = new Vector3d(20, 3.2, 2.2);
            var spin = new LaunchSpin(0, 61.86);
            AimSolution aim = new AimSolver(model, RungeKutta4.Instance, 1.0 / 240, ground).AnglesToReach(start, 24.15, spin, target);
            var frame = new LaunchFrame(Vector3d.UnitZ, target - start);
            Vector3d direction = frame.Direction(aim.ElevationRadians, aim.AzimuthFromTargetRadians);
            var predictor = new TrajectoryPredictor(
                model, RungeKutta4.Instance, 1.0 / 240, new FlightEventSet(Vector3d.UnitZ, ground, new[] { new Plane(new Vector3d(20, 0, 0), Vector3d.UnitX) }));
            return new[] { 19.32, 24.15, 28.91 }
                .Select(v => predictor.Predict(new FlightState(start, direction * v, spin.AngularVelocity(direction, frame)), 10, Span<Vector3d>.Empty,
                    FlightEventKinds.Landing | FlightEventKinds.PlaneCrossing).EndState.Position.Y)
                .ToArray();
        }

        [Test]
        public async Task SelfTest_HashEqualsCoreClrs()
        {
            const int shots = 2000;
            var here = new DeterminismShots();
            string summary = here.Run(shots, TextWriter.Null);

            IPage page = await PlaygroundHost.OpenAsync($"?selftest={shots}");
            await page.WaitForSelectorAsync("#determinism-hash", new PageWaitForSelectorOptions { Timeout = 300_000 });
            string browser = await page.InnerTextAsync("#determinism-hash");
            TestContext.Out.WriteLine($"browser: {browser}; CoreCLR: {here.HashText} ({await page.InnerTextAsync("#selftest-status")})");
            Assert.That(browser, Is.EqualTo(here.HashText));
            Assert.That(await page.InnerTextAsync("#determinism-summary"), Is.EqualTo(summary));
        }

        [Test]
        public async Task ChangingSpin_ChangesTheCurve_AndTheLinkKeepsIt()
        {
            IPage page = await PlaygroundHost.OpenAsync();
            string before = await page.GetAttributeAsync("#path-side", "d") ?? string.Empty;
            double landingBefore = await CellValue(page, "#row-landing-x td:nth-child(2)");

            var clock = System.Diagnostics.Stopwatch.StartNew();
            await page.FillAsync("#in-top", "3000");
            await page.PressAsync("#in-top", "Tab");
            await page.WaitForFunctionAsync("d => document.querySelector('#path-side').getAttribute('d') !== d", before);
            TestContext.Out.WriteLine($"a tennis shot, its second shot and their references redrawn in {clock.ElapsedMilliseconds} ms");
            clock.Restart();
            await page.FillAsync("#in-rate", "120");
            await page.PressAsync("#in-rate", "Tab");
            await page.WaitForFunctionAsync("() => new URL(location.href).searchParams.get('rate') === '120'");
            TestContext.Out.WriteLine($"the same at another rate (references kept) in {clock.ElapsedMilliseconds} ms");
            await page.FillAsync("#in-rate", "240");
            await page.PressAsync("#in-rate", "Tab");
            await page.WaitForFunctionAsync("() => new URL(location.href).searchParams.get('rate') === '240'");
            string after = await page.GetAttributeAsync("#path-side", "d") ?? string.Empty;
            double landingAfter = await CellValue(page, "#row-landing-x td:nth-child(2)");
            Assert.That(after, Is.Not.EqualTo(before));
            Assert.That(landingAfter, Is.LessThan(landingBefore), "more topspin dips the ball: it lands shorter");
            Assert.That(page.Url, Does.Contain("top=3000"), "the address carries the state");

            // The shared link opens the same shot.
            IPage shared = await PlaygroundHost.OpenAsync(new Uri(page.Url).Query);
            await shared.WaitForSelectorAsync("#path-side");
            Assert.That(await shared.GetAttributeAsync("#path-side", "d"), Is.EqualTo(after));
            Assert.That(await shared.InputValueAsync("#in-top"), Is.EqualTo("3000"));
        }

        [Test]
        public async Task RefusedInput_ShowsItsMessage_AndKeepsTheLastShot()
        {
            IPage page = await PlaygroundHost.OpenAsync();
            string before = await page.GetAttributeAsync("#path-side", "d") ?? string.Empty;
            await page.FillAsync("#in-speed", "500");
            await page.PressAsync("#in-speed", "Enter");
            ILocator message = page.Locator("#message");
            await message.WaitForAsync();
            Assert.That(await message.InnerTextAsync(), Does.Contain("Speed (m/s) must be from 0.5 to 100; got 500."));
            Assert.That(await page.GetAttributeAsync("#path-side", "d"), Is.EqualTo(before));

            IPage fromLink = await PlaygroundHost.OpenAsync("?preset=tennis&rate=abc");
            Assert.That(await fromLink.InnerTextAsync("#message"), Does.Contain("Steps per second (1/s) must be a number; got 'abc'."));
            await fromLink.WaitForSelectorAsync("#path-side");

            // A step beyond explicit Euler's stability bound for a light, fast, spinning ball is reported as unreliable, not as a landing.
            // (12,000 rpm: the lift adds to the drag rate, h sigma about 2.4 against Euler's 2.)
            IPage unstable = await PlaygroundHost.OpenAsync("?preset=table-tennis&speed=100&elev=5&top=12000&method=euler&rate=10&cmp=none");
            Assert.That(await unstable.Locator("#row-outcome td").First.InnerTextAsync(), Is.EqualTo("unreliable: the step is beyond the method's stability bound"));
            Assert.That(await unstable.InnerTextAsync("#message"), Does.Contain("10 steps per second are too few for euler"));
            Assert.That(await unstable.GetAttributeAsync("#row-landing-x [data-value]", "data-value"), Is.Empty, "no landing is reported");

            // A bad self-test count says so instead of flying nothing.
            IPage selfTest = await PlaygroundHost.OpenAsync("?selftest=abc");
            Assert.That(await selfTest.InnerTextAsync("#message"), Does.Contain("selftest must be a whole number of shots from 1 to 100000; got 'abc'."));
            Assert.That(await selfTest.Locator("#determinism-hash").CountAsync(), Is.Zero);
        }

        [Test]
        public async Task AimingAtATarget_LandsThere()
        {
            IPage page = await PlaygroundHost.OpenAsync();
            await page.FillAsync("#in-tx", "20");
            await page.FillAsync("#in-ty", "2");
            await page.ClickAsync("#aim");
            await page.WaitForFunctionAsync("() => document.querySelector('.aim') !== null");
            await page.WaitForFunctionAsync("() => new URL(location.href).searchParams.get('dir') !== '0'");
            Assert.That(await page.InnerTextAsync("#aim-result"), Does.StartWith("Aimed at (20, 2) m: elevation"));
            double x = await CellValue(page, "#row-landing-x td:nth-child(2)");
            double y = await CellValue(page, "#row-landing-y td:nth-child(2)");
            // 1 mm: the solver's trials (adaptive Dormand-Prince at 1e-8) agree with the page's RK4 at 1/240 s to
            // 2e-8 rad and 1e-7 m/s (AimSolver's docs), a few micrometres at 20 m.
            Assert.That(x, Is.EqualTo(20).Within(1e-3));
            Assert.That(y, Is.EqualTo(2).Within(1e-3));

            // The aimed shot's link opens the same shot.
            string path = await page.GetAttributeAsync("#path-side", "d") ?? string.Empty;
            IPage shared = await PlaygroundHost.OpenAsync(new Uri(page.Url).Query);
            await shared.WaitForSelectorAsync("#path-side");
            Assert.That(await shared.Locator("#message").CountAsync(), Is.Zero, "the link is accepted");
            Assert.That(await shared.GetAttributeAsync("#path-side", "d"), Is.EqualTo(path));

            // A target whose launch the page cannot carry (68 degrees to the side) is refused, and the shot stays.
            await page.FillAsync("#in-tx", "2");
            await page.FillAsync("#in-ty", "5");
            await page.ClickAsync("#aim");
            await page.Locator("#message").WaitForAsync();
            Assert.That(await page.InnerTextAsync("#message"), Does.Contain("Direction (deg, + left) must be from -60 to 60"));
            Assert.That(await page.GetAttributeAsync("#path-side", "d"), Is.EqualTo(path));
        }

        [Test]
        public async Task NarrowScreen_FitsWithoutSideScrolling_AndEveryInputHasALabel()
        {
            IPage page = await PlaygroundHost.OpenAsync(width: 390, height: 844);
            await page.WaitForSelectorAsync("#path-side");
            bool fits = await page.EvaluateAsync<bool>("() => document.documentElement.scrollWidth <= window.innerWidth");
            Assert.That(fits, Is.True, "no horizontal scrolling at 390 px");
            int unlabelled = await page.EvaluateAsync<int>(
                "() => [...document.querySelectorAll('input, select')].filter(e => !document.querySelector(`label[for=\"${e.id}\"]`)).length");
            Assert.That(unlabelled, Is.Zero);
            string narrow = Path.Combine(TestContext.CurrentContext.WorkDirectory, "playground-narrow.png");
            await page.ScreenshotAsync(new PageScreenshotOptions { Path = narrow, FullPage = true });
            TestContext.AddTestAttachment(narrow, "the playground at 390 px");
        }

        [Test]
        public async Task Screenshot_OfTheDefaultPage()
        {
            IPage page = await PlaygroundHost.OpenAsync("?cmp=nospin");
            await page.WaitForSelectorAsync("#path2-side");
            string file = Path.Combine(TestContext.CurrentContext.WorkDirectory, "playground.png");
            await page.ScreenshotAsync(new PageScreenshotOptions { Path = file, FullPage = true });
            TestContext.AddTestAttachment(file, "the playground: a topspin forehand against the same shot without spin");
            Assert.That(new FileInfo(file).Length, Is.GreaterThan(10_000));
        }

        [Test]
        public void PublishedDownload_IsAtMostThreeMegabytesBrotli()
        {
            long brotli = Directory.EnumerateFiles(PlaygroundHost.SiteRoot, "*.br", SearchOption.AllDirectories).Sum(f => new FileInfo(f).Length);
            TestContext.Out.WriteLine($"published, Brotli: {brotli / 1e6:0.00} MB");
            Assert.That(brotli, Is.LessThanOrEqualTo(3_000_000), "issue 41's target");
        }
    }
}
