#include "cs2config/LayoutCheck.h"

#include "cs2config/Text.h"
#include "cs2config/TileArticle.h"

#include <algorithm>
#include <map>
#include <tuple>

namespace stellwerk::cs2config {

namespace {

constexpr std::string_view indexName = "gleisbild.cs2";
// From this many tiles that do not fit on a page (and at least half of them), one finding stands for all.
constexpr std::size_t manyMisfits = 10;

std::string_view trimmed(std::string_view text) {
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t'))
        text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t'))
        text.remove_suffix(1);
    return text;
}

char lower(char c) {
    return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c;
}

// A tile's label and an article's name agree when they are the same, or one is the first words of the
// other: a tile labelled "W1" for the article "W1 Einfahrt West" (the CS2 has little room on a tile).
bool sameLabel(std::string_view label, std::string_view name) {
    label = trimmed(label);
    name = trimmed(name);
    const std::string_view shorter = label.size() <= name.size() ? label : name;
    const std::string_view longer = label.size() <= name.size() ? name : label;
    for (std::size_t i = 0; i < shorter.size(); ++i)
        if (lower(shorter[i]) != lower(longer[i]))
            return false;
    return shorter.size() == longer.size() || longer[shorter.size()] == ' ' || longer[shorter.size()] == '-';
}

// "tile '23' (rechtsweiche at column 5, row 1)"
std::string describe(const TrackElement& element) {
    std::string text = "tile ";
    if (!element.text.empty())
        text += quoteForMessage(element.text) + " ";
    return text + "(" + (element.type.empty() ? std::string("text") : element.type) + " at column " +
           std::to_string(element.position.column) + ", row " + std::to_string(element.position.row) + ")";
}

// "article 1 '23'"
std::string describe(const Accessory& article) {
    std::string text = "article " + std::to_string(article.id);
    if (article.secondOutput)
        text += " (second output)";
    return article.name.empty() ? text : text + " " + quoteForMessage(article.name);
}

std::string pageFileName(const TrackLayoutPage& page) {
    return page.diagnostics.fileName();
}

} // namespace

std::string LayoutFinding::format(const std::filesystem::path& directory) const {
    const std::string where =
        directory.empty() ? file : (directory / std::u8string(file.begin(), file.end())).string();
    return where + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": warning: " + message;
}

LayoutCheck::LayoutCheck(const TrackLayout& layout, const AccessoryFile* accessories)
    : layout_(layout), accessories_(accessories) {}

std::vector<LayoutFinding> LayoutCheck::run() {
    findings_.clear();
    checkMissingPages();
    const std::vector<PlacedTile> tiles = accessoryTiles();
    checkSharedArticles(tiles);
    if (accessories_)
        checkPageByPage(tiles);
    // In file and line order, as a person goes through the files.
    std::stable_sort(findings_.begin(), findings_.end(), [](const LayoutFinding& a, const LayoutFinding& b) {
        return std::tie(a.file, a.line) < std::tie(b.file, b.line);
    });
    return std::move(findings_);
}

// The tiles come page by page (accessoryTiles keeps the file order).
void LayoutCheck::checkPageByPage(const std::vector<PlacedTile>& tiles) {
    for (std::size_t first = 0; first < tiles.size();) {
        std::size_t end = first;
        while (end < tiles.size() && tiles[end].page == tiles[first].page)
            ++end;
        checkPageTiles({tiles.begin() + std::ptrdiff_t(first), tiles.begin() + std::ptrdiff_t(end)});
        first = end;
    }
}

// One finding per missing page; one for the whole folder when no page file is there at all.
void LayoutCheck::checkMissingPages() {
    std::vector<std::size_t> missing;
    for (std::size_t i = 0; i < layout_.pages.size(); ++i)
        if (layout_.pages[i].missing)
            missing.push_back(i);
    if (missing.size() > 1 && missing.size() == layout_.pages.size()) {
        findings_.push_back({std::string(indexName), 0,
                             "none of the " + std::to_string(missing.size()) +
                                 " pages it lists has its file in gleisbilder/; the track plan stays empty"});
        return;
    }
    for (const std::size_t i : missing) {
        const TrackLayoutPage& page = layout_.pages[i];
        const int line = i < layout_.plan.pages.size() ? layout_.plan.pages[i].line() : 0;
        findings_.push_back({std::string(indexName), line,
                             "page " + std::to_string(page.id) + " " + quoteForMessage(page.name, 80) +
                                 " is listed, but its file " + quoteForMessage(pageFileName(page), 80) +
                                 " is missing; the page stays empty"});
    }
}

std::vector<LayoutCheck::PlacedTile> LayoutCheck::accessoryTiles() const {
    std::vector<PlacedTile> tiles;
    for (const TrackLayoutPage& page : layout_.pages)
        for (const TrackElement& element : page.page.elements)
            if (element.accessoryId())
                tiles.push_back({&page, &element});
    return tiles;
}

// Tiles with the same `.artikel` switch the same output of the same article: one finding per article,
// at its first tile, naming the others.
void LayoutCheck::checkSharedArticles(const std::vector<PlacedTile>& tiles) {
    std::map<std::int64_t, std::vector<const PlacedTile*>> byArticle;
    for (const PlacedTile& tile : tiles)
        byArticle[tile.element->article].push_back(&tile);
    for (const auto& [number, sharing] : byArticle) {
        if (sharing.size() < 2)
            continue;
        const Accessory* article =
            accessories_ ? articleOfTile(*sharing.front()->element, *accessories_) : nullptr;
        std::string others;
        for (std::size_t i = 1; i < sharing.size(); ++i)
            others += (i > 1 ? ", " : "") + describe(*sharing[i]->element) + " in " +
                      pageFileName(*sharing[i]->page) + ":" + std::to_string(sharing[i]->element->line());
        report(*sharing.front(), describe(*sharing.front()->element) + " and " +
                                     std::to_string(sharing.size() - 1) +
                                     (sharing.size() == 2 ? " other tile" : " other tiles") +
                                     " switch the same " + (article ? describe(*article) : "article") +
                                     " (.artikel=" + std::to_string(number) + "): " + others);
    }
}

// The tiles of one page against magnetartikel.cs2. When most of them link to articles that are not
// there or are of another kind, the page and the file do not belong together (another station's
// magnetartikel.cs2, other numbers): one finding says so instead of one per tile.
void LayoutCheck::checkPageTiles(const std::vector<PlacedTile>& tiles) {
    std::vector<LayoutFinding> misfits;
    for (const PlacedTile& tile : tiles)
        if (std::optional<std::string> misfit = checkTile(tile))
            misfits.push_back({pageFileName(*tile.page), tile.element->line(), std::move(*misfit)});
    if (misfits.size() < manyMisfits || misfits.size() * 2 < tiles.size()) {
        findings_.insert(findings_.end(), misfits.begin(), misfits.end());
        return;
    }
    findings_.push_back({pageFileName(*tiles.front().page), 0,
                         std::to_string(misfits.size()) + " of its " + std::to_string(tiles.size()) +
                             " accessory tiles link to articles that magnetartikel.cs2 does not have or that "
                             "are of another kind (first " +
                             misfits.front().message +
                             "); the page and magnetartikel.cs2 do not seem to belong together"});
}

// Why the tile does not fit its article (missing, of another kind); a label that disagrees is reported
// right here for a tile that fits.
std::optional<std::string> LayoutCheck::checkTile(const PlacedTile& tile) {
    const Accessory* article = articleOfTile(*tile.element, *accessories_);
    if (!article)
        return describe(*tile.element) + " switches article " + std::to_string(*tile.element->accessoryId()) +
               " (.artikel=" + std::to_string(tile.element->article) +
               "), which magnetartikel.cs2 does not have";
    if (const std::string mismatch = tileArticleMismatch(*tile.element, *article); !mismatch.empty())
        return describe(*tile.element) + " switches " + describe(*article) + ", a " + article->type + ": " +
               mismatch;
    checkLabel(tile, *article);
    return std::nullopt;
}

// A label that names another article points at the `.artikel` the tile probably should have.
void LayoutCheck::checkLabel(const PlacedTile& tile, const Accessory& article) {
    const std::string_view label = trimmed(tile.element->text);
    if (label.empty() || trimmed(article.name).empty() || sameLabel(label, article.name))
        return;
    std::string message = describe(*tile.element) + " is labelled " + quoteForMessage(label) +
                          " but switches " + describe(article);
    for (const Accessory& other : accessories_->accessories)
        if (&other != &article && sameLabel(label, other.name)) {
            message += "; " + quoteForMessage(other.name) + " is article " + std::to_string(other.id) +
                       " (.artikel=" + std::to_string(other.id * 2 + (other.secondOutput ? 1 : 0)) + ")";
            break;
        }
    report(tile, std::move(message));
}

void LayoutCheck::report(const PlacedTile& tile, std::string message) {
    findings_.push_back({pageFileName(*tile.page), tile.element->line(), std::move(message)});
}

} // namespace stellwerk::cs2config
