using System;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Threading.Tasks;
using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Hosting;
using Microsoft.AspNetCore.Hosting.Server;
using Microsoft.AspNetCore.Hosting.Server.Features;
using Microsoft.AspNetCore.StaticFiles;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.FileProviders;
using Microsoft.Extensions.Logging;
using Microsoft.Playwright;
using NUnit.Framework;

namespace MagnusBall.Playground.Tests
{
    /// <summary>
    /// Serves the published playground on 127.0.0.1 (an in-process Kestrel static server on a free port) and starts
    /// Debian's Chromium headless through Playwright, once for every test. The published app is taken from
    /// MAGNUSBALL_PLAYGROUND_SITE (tools/test-playground.sh publishes it there), or published into
    /// artifacts/playground-site on first use.
    /// </summary>
    [SetUpFixture]
    public sealed class PlaygroundHost
    {
        /// <summary>Debian's Chromium: Playwright's own browser download cannot be reached here, and is not needed.</summary>
        public const string ChromiumPath = "/usr/bin/chromium";

        private static WebApplication? _server;
        private static IPlaywright? _playwright;

        /// <summary>The address the app is served at, ending in '/'.</summary>
        public static string BaseUrl { get; private set; } = string.Empty;

        /// <summary>The published app's wwwroot.</summary>
        public static string SiteRoot { get; private set; } = string.Empty;

        /// <summary>The browser.</summary>
        public static IBrowser Browser { get; private set; } = null!;

        /// <summary>Publishes the app if needed, serves it, starts the browser.</summary>
        [OneTimeSetUp]
        public async Task Start()
        {
            if (!File.Exists(ChromiumPath))
            {
                Assert.Fail($"These tests need Debian's Chromium at {ChromiumPath}: apt-get install chromium (tools/test-playground.sh does).");
            }

            string repository = RepositoryRoot();
            string site = Environment.GetEnvironmentVariable("MAGNUSBALL_PLAYGROUND_SITE") ?? Path.Combine(repository, "artifacts", "playground-site");
            SiteRoot = Path.Combine(site, "wwwroot");
            if (!File.Exists(Path.Combine(SiteRoot, "index.html")))
            {
                Publish(repository, site);
            }

            WebApplicationBuilder builder = WebApplication.CreateBuilder(new WebApplicationOptions { ContentRootPath = SiteRoot, WebRootPath = SiteRoot });
            builder.Logging.ClearProviders();
            builder.WebHost.UseUrls("http://127.0.0.1:0");
            _server = builder.Build();
            var types = new FileExtensionContentTypeProvider();
            types.Mappings[".wasm"] = "application/wasm";
            types.Mappings[".dat"] = "application/octet-stream";
            types.Mappings[".blat"] = "application/octet-stream";
            var files = new PhysicalFileProvider(SiteRoot);
            _server.UseDefaultFiles(new DefaultFilesOptions { FileProvider = files });
            _server.UseStaticFiles(new StaticFileOptions { FileProvider = files, ContentTypeProvider = types });
            _server.MapFallbackToFile("index.html", new StaticFileOptions { FileProvider = files });
            await _server.StartAsync();
            string address = _server.Services.GetRequiredService<IServer>().Features.Get<IServerAddressesFeature>()!.Addresses.First();
            BaseUrl = address.TrimEnd('/') + "/";

            _playwright = await Microsoft.Playwright.Playwright.CreateAsync();
            Browser = await _playwright.Chromium.LaunchAsync(new BrowserTypeLaunchOptions
            {
                ExecutablePath = ChromiumPath,
                Headless = true,
                // As root in a closed network: no sandbox, and none of Chromium's background connections.
                Args = new[]
                {
                    "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
                    "--disable-component-update", "--disable-sync",
                },
            });
        }

        /// <summary>Closes the browser and the server.</summary>
        [OneTimeTearDown]
        public async Task Stop()
        {
            if (Browser is not null)
            {
                await Browser.CloseAsync();
            }

            _playwright?.Dispose();
            if (_server is not null)
            {
                await _server.StopAsync();
                await _server.DisposeAsync();
            }
        }

        private static readonly System.Collections.Generic.List<(IBrowserContext Context, IPage Page, System.Collections.Generic.List<string> Errors)> Opened =
            new System.Collections.Generic.List<(IBrowserContext, IPage, System.Collections.Generic.List<string>)>();

        /// <summary>
        /// A new page (its own context) at the app's address with <paramref name="query"/>, loaded. Its uncaught errors
        /// and console errors (where Blazor reports an exception in an event handler) are collected for <see cref="CloseAllAsync"/>.
        /// </summary>
        public static async Task<IPage> OpenAsync(string query = "", int width = 1280, int height = 900)
        {
            IBrowserContext context = await Browser.NewContextAsync(new BrowserNewContextOptions { ViewportSize = new ViewportSize { Width = width, Height = height } });
            IPage page = await context.NewPageAsync();
            var errors = new System.Collections.Generic.List<string>();
            page.PageError += (_, e) => errors.Add("page error: " + e);
            page.Console += (_, m) =>
            {
                if (m.Type == "error")
                {
                    errors.Add("console error: " + m.Text);
                }
            };
            Opened.Add((context, page, errors));
            await page.GotoAsync(BaseUrl + query);
            await page.WaitForSelectorAsync("h1", new PageWaitForSelectorOptions { Timeout = 120_000 });
            Assert.That(errors, Is.Empty, "the page threw while loading");
            return page;
        }

        /// <summary>
        /// Asserts that no page opened since the last call threw or showed Blazor's error bar (#blazor-error-ui), then
        /// closes them all.
        /// </summary>
        public static async Task CloseAllAsync()
        {
            var problems = new System.Collections.Generic.List<string>();
            foreach ((IBrowserContext context, IPage page, System.Collections.Generic.List<string> errors) in Opened)
            {
                problems.AddRange(errors);
                if (!page.IsClosed && await page.IsVisibleAsync("#blazor-error-ui"))
                {
                    problems.Add("Blazor's error bar is shown at " + page.Url);
                }

                await context.CloseAsync();
            }

            Opened.Clear();
            Assert.That(problems, Is.Empty, "the app reported an error");
        }

        private static string RepositoryRoot()
        {
            string? dir = TestContext.CurrentContext.TestDirectory;
            while (dir is not null && !File.Exists(Path.Combine(dir, "MagnusBall.sln")))
            {
                dir = Path.GetDirectoryName(dir);
            }

            return dir ?? throw new InvalidOperationException("MagnusBall.sln not found above " + TestContext.CurrentContext.TestDirectory);
        }

        private static void Publish(string repository, string site)
        {
            var start = new ProcessStartInfo("dotnet", $"publish samples/Playground -c Release -o \"{site}\" -nologo -v quiet")
            {
                WorkingDirectory = repository,
                RedirectStandardOutput = true,
                RedirectStandardError = true,
            };
            using Process process = Process.Start(start)!;
            string output = process.StandardOutput.ReadToEnd() + process.StandardError.ReadToEnd();
            if (!process.WaitForExit(600_000) || process.ExitCode != 0)
            {
                Assert.Fail("dotnet publish samples/Playground failed:\n" + output);
            }
        }
    }
}
